// Example 2: build a job in memory (no JSON file) and convert it for a
// machine profile, in arcs mode, printing the G-code.
//
//   build/examples/convert_in_memory MACHINES_DIR [PROFILE]
#include <bezcam/bezcam.hpp>
#include <cstdio>
#include <iostream>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: convert_in_memory MACHINES_DIR [PROFILE]\n");
    return 2;
  }
  try {
    using bezcam::Bezier;
    // A closed outline of two cubic segments: a lens shape.
    const bezcam::Job job = bezcam::JobBuilder("lens")
                                .tolerance(0.01)
                                .feed(800)
                                .plunge_feed(200)
                                .safe_z(5)
                                .cut_z(-0.5)
                                .spindle_rpm(12000)
                                .path("lens",
                                      {Bezier::make({{0, 0, 0}, {10, 15, 0}, {40, 15, 0}, {50, 0, 0}}),
                                       Bezier::make({{50, 0, 0}, {40, -15, 0}, {10, -15, 0}, {0, 0, 0}})},
                                      /*closed=*/true)
                                .build();
    const bezcam::MachineProfile m =
        bezcam::load_machine_profile(argc > 2 ? argv[2] : "linuxcnc", bezcam::machine_search_path({argv[1]}));
    bezcam::ConvertOptions opt;
    opt.output = bezcam::OutputMode::arcs;
    const bezcam::ConvertResult r = bezcam::convert(job, m, opt);
    std::cout << r.gcode;
    std::fprintf(stderr, "%zu moves; largest deviation measured %.4g mm, proven bound %.4g mm\n",
                 r.program.moves.size(), r.program.max_measured, r.program.max_bound);
    return 0;
  } catch (const bezcam::Error& e) {
    std::fprintf(stderr, "error %s: %s\n", e.id().c_str(), e.what());
    return 2;
  }
}

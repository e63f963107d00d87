// Example 3: start the simulated controller on a free port of 127.0.0.1,
// stream a program to it over Modbus TCP, and print what it executed.
//
//   build/examples/stream_to_simulator MACHINES_DIR
#include <bezcam/bezcam.hpp>
#include <cstdio>
#include <mutex>
#include <string>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: stream_to_simulator MACHINES_DIR\n");
    return 2;
  }
  try {
    std::mutex mu;
    std::string trace;  // what the controller executed (its trace)
    bezcam::sim::ControllerConfig cfg;
    cfg.profile = bezcam::load_machine_profile("generic", bezcam::machine_search_path({argv[1]}));
    cfg.first_session = 1;
    cfg.trace = [&](std::string_view text, bool restart) {
      std::lock_guard lk(mu);
      if (restart) trace.clear();
      trace += text;
    };
    bezcam::sim::SimController controller(std::move(cfg));
    bezcam::sim::ServerConfig scfg;  // 127.0.0.1, a free port
    bezcam::sim::ModbusServer server(controller, scfg);
    server.start();  // listening once constructed: no wait needed

    const std::string program =
        "%\nG21 G90 G17\nG00 Z5.\nG00 X0. Y0.\nM03 S10000\nG01 Z-0.5 F200.\n"
        "G02 X20. Y0. I10. J0. F600.\nG01 X0. Y0.\nG00 Z5.\nM05\nM30\n%\n";
    bezcam::link::StreamOptions opt;
    const bezcam::link::StreamResult r = bezcam::link::stream_program(program, {"127.0.0.1", server.port()}, opt);
    server.stop();
    controller.stop();
    std::printf("sent %llu bytes in %llu chunks; the controller executed %u lines, %u blocks\n",
                static_cast<unsigned long long>(r.bytes), static_cast<unsigned long long>(r.chunks), r.lines_executed,
                r.blocks_executed);
    std::lock_guard lk(mu);
    std::printf("%s", trace.c_str());
    return r.blocks_executed > 0 ? 0 : 1;
  } catch (const bezcam::Error& e) {
    std::fprintf(stderr, "error %s: %s\n", e.id().c_str(), e.what());
    return 2;
  }
}

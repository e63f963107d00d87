// --machine, --tolerance, --output, --strict, --set and --layer.
#include "conversion_options.hpp"

#include "bezcam/error.hpp"
#include "bezcam/warnings.hpp"
#include "validators.hpp"

namespace bezcam::cli {

void add_conversion_options(CLI::App* s, ConversionOptions& o, const std::string& output_help, bool takes_best) {
  s->add_option("--machine", o.machine,
                "machine profile: a name in machines/ or a .json file "
                "(default: the job's \"machine\", else generic)");
  s->add_option("--tolerance", o.tolerance, "chord tolerance in the job's units, overriding the job's")
      ->check(positive_number());
  s->add_option("--output", o.output, output_help)
      ->check(CLI::Validator(
          [takes_best](std::string& v) -> std::string {
            if (v == "lines" || v == "arcs" || v == "nurbs" || (takes_best && v == "best")) return {};
            const std::string expected = takes_best ? "lines, arcs, nurbs or best" : "lines, arcs or nurbs";
            // `--output out.nc`: the program's file is -o.
            if (v.find('.') != std::string::npos || v.find('/') != std::string::npos)
              return "expected " + expected + ", found \"" + v + "\"; to name the program file, use -o " + v;
            if (v == "best") return "expected " + expected + ": best is taken by convert, check and sheet";
            return "expected " + expected + ", found \"" + v + "\"";
          },
          takes_best ? "lines|arcs|nurbs|best" : "lines|arcs|nurbs"))
      ->capture_default_str();
  s->add_flag("--strict", o.strict,
              "take every warning as an error: exit status 2, nothing written (every unknown key of a job "
              "is refused, with or without it)");
  std::string kinds;
  for (std::string_view k : kWarningKinds) kinds += (kinds.empty() ? "" : ", ") + std::string(k);
  s->add_option("--no-warn", o.no_warn, "leave out warnings of this kind, repeatable: " + kinds)
      ->type_name("KIND")
      ->check(CLI::Validator(
          [](std::string& v) {
            if (is_warning_kind(v)) return std::string();
            std::string known;
            for (std::string_view k : kWarningKinds) known += (known.empty() ? "" : ", ") + std::string(k);
            return "expected a warning kind (" + known + "), found \"" + v + "\"";
          },
          "KIND"));
  add_drawing_options(s, o);
}

void add_drawing_options(CLI::App* s, ConversionOptions& o) {
  s->add_option("--set", o.sets,
                "a job setting for a drawing (.svg, .dxf), KEY=VALUE, repeatable: any key of the "
                "job file's \"job\" object (feed, cut_z, side, tool_diameter ...) or tolerance, units, "
                "machine; dotted keys nest (tabs.count=4), VALUE is JSON when it reads as JSON "
                "(lead={\"radius\":4}), else text; an unknown key is refused. SELECTOR:KEY=VALUE sets an "
                "entity's key on the entities whose layer or id matches SELECTOR, a glob ('HOLES*:tool=2')")
      ->type_name("[SELECTOR:]KEY=VALUE");
  s->add_option("--layer", o.layers, "a layer of the drawing to cut, repeatable (default: every layer)")
      ->type_name("NAME");
  s->add_option("--only", o.only,
                "cut only the drawing's entities whose layer or id matches SELECTOR, a glob; repeatable")
      ->type_name("SELECTOR");
  s->add_option("--join-tolerance", o.join_tolerance,
                "join a DXF's entities whose ends are at most D apart (mm, after --scale), moving the ends to "
                "meet; each gap wider than the default (1e-6 of the drawing's size) is reported")
      ->type_name("D")
      ->check(positive_number());
  s->add_option("--scale", o.scale, "multiply the drawing's coordinates by S")
      ->type_name("S")
      ->check(positive_number());
  s->add_option("--units", o.units,
                "what a drawing unit is when the drawing does not say (DXF $INSUNITS 0 or absent, SVG "
                "without units): um, mm, cm, m, inch or foot; a drawing that says another unit is refused")
      ->type_name("U")
      ->check(CLI::IsMember({"um", "mm", "cm", "m", "inch", "foot"}));
  s->add_option("--skip", o.skip,
                "leave out the drawing's entities whose layer or id matches SELECTOR, a glob; repeatable")
      ->type_name("SELECTOR");
}

void refuse_best_without_motion(const MachineProfile& m) {
  if (!m.motion)
    throw InputError(errc::usage_output, Place::at_option("--output"),
                     "best chooses by the planned cycle time, and machine \"" + m.name +
                         "\" has no motion model (key \"motion\", docs/machines.md) to plan it with; choose lines, "
                         "arcs or nurbs");
}

}  // namespace bezcam::cli

// The examples that end each command's --help (and the man page made from
// it): command lines that run as written from a folder holding the
// samples, in the order the commands are listed (tests/cli run them).
#include "help_examples.hpp"

#include <string>
#include <vector>

#include "bezcam/version.hpp"

namespace bezcam::cli {

const std::vector<std::pair<std::string, std::vector<std::string>>>& help_examples() {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> examples = {
      {"check",
       {"bezcam check samples/part-flange.json --machine fanuc",
        "bezcam check samples/part.dxf --join-tolerance 0.001"}},
      {"convert",
       {"bezcam convert samples/part-flange.json --machine fanuc --output arcs -o flange.nc",
        "bezcam convert samples/part.dxf --machine linuxcnc --set cut_z=-1 --set feed=600 -o part.ngc"}},
      {"import",
       {"bezcam import samples/part.dxf -o part.json", "bezcam import samples/logo.svg --scale 0.5 -o logo.json"}},
      {"lint", {"bezcam lint flange.nc --machine fanuc"}},
      {"preview",
       {"bezcam preview samples/part-flange.json --output arcs -o flange.svg",
        "bezcam preview --program part.ngc --machine linuxcnc -o part.svg"}},
      {"sheet", {"bezcam sheet samples/part-flange-tools.json --machine fanuc -o flange.html"}},
      {"simulate",
       {"bezcam simulate --program flange.nc --machine fanuc --report flange.json",
        "bezcam simulate --listen 127.0.0.1:5020 --machine linuxcnc"}},
      {"verify", {"bezcam verify flange.nc --machine fanuc --design samples/part-flange.json --image flange.png"}},
  };
  return examples;
}

void add_help_examples(CLI::App& app) {
  for (const auto& [name, lines] : help_examples()) {
    CLI::App* sub = app.get_subcommand(name);
    std::string text = sub->get_footer();
    if (!text.empty()) text += "\n\n";
    text += "Examples:";
    for (const auto& l : lines) text += "\n  " + l;
    sub->footer(text);
  }
  app.footer(std::string("A drawing to a checked LinuxCNC program, previewed:\n") +
             "  bezcam convert part.dxf --machine linuxcnc --set cut_z=-1 -o part.ngc\n"
             "  bezcam lint part.ngc --machine linuxcnc\n"
             "  bezcam preview --program part.ngc --machine linuxcnc -o part.svg\n"
             "Each command's --help ends with examples. Manual: man bezcam; documentation: " +
             kInstallDocDir + " (docs/ in the source).");
}

}  // namespace bezcam::cli

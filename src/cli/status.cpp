// bezcam status --to HOST:PORT: what a controller is doing (state, line,
// alarm, buffer, machine), read from its status registers. Exit 0 when it
// answered, 3 when it cannot be reached.
#include <iostream>

#include "bezcam/link/streamer.hpp"
#include "commands.hpp"
#include "validators.hpp"

namespace bezcam::cli {

using namespace bezcam::link;

CLI::App* setup_status(CLI::App& app, StatusArgs& o) {
  auto* s = app.add_subcommand("status",
                               "Print what a controller is doing: state, lines executed, alarm and its "
                               "line, buffer, spindle, tool and the machine profile it enforces.");
  s->add_option("--to", o.to, "controller address HOST:PORT")->required();
  s->add_option("--timeout", o.timeout, "seconds to wait for its reply")
      ->check(positive_number())
      ->capture_default_str();
  s->footer("Examples:\n  bezcam status --to 127.0.0.1:5020\n  bezcam status --to 192.168.0.10:502 --timeout 5");
  return s;
}

int run_status(const StatusArgs& o) {
  const Endpoint to = parse_endpoint(o.to);
  print_controller(controller_status(to, std::chrono::milliseconds(static_cast<long long>(o.timeout * 1000.0 + 0.5))),
                   to);
  return 0;
}

void print_controller(const ControllerReport& r, const Endpoint& to) {
  const Status& s = r.status;
  std::cout << to.str() << ": state " << to_string(s.state);
  if (s.state == State::alarm)
    std::cout << ", alarm " << to_string(s.alarm)
              << (!r.alarm_text.empty() ? ": " + r.alarm_text
                  : s.alarm_line        ? " at line " + std::to_string(s.alarm_line)
                                        : std::string());
  std::cout << "\n  machine " << (r.machine.empty() ? "(unnamed)" : r.machine) << ", " << s.lines_executed
            << " lines executed, " << s.ack_bytes << " bytes acknowledged, buffer " << s.buffer_free << " of "
            << s.buffer_capacity << " bytes free, spindle " << ((s.flags & flag::spindle_on) ? "on" : "off")
            << ", tool " << s.tool << ", " << s.connections << " connection" << (s.connections == 1 ? "" : "s")
            << ", starved " << s.starved_ms << " ms (" << s.stalls << (s.stalls == 1 ? " stall)" : " stalls)") << "\n";
}

}  // namespace bezcam::cli

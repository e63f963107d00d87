// The command line: the app and its subcommands, usage errors, and the
// refusals of a run shown as the program's messages and exit statuses.
#include "command_line.hpp"

#include <iostream>
#include <new>
#include <string_view>
#include <utility>

#include "bezcam/error.hpp"
#include "bezcam/job/keys.hpp"
#include "bezcam/version.hpp"
#include "exit_status.hpp"
#include "help_examples.hpp"

namespace bezcam::cli {

CommandLine::CommandLine()
    : app_(
          "bezcam: exact curves and surfaces (JSON) to CNC programs whose chord error is proven, "
          "streamed to controllers over Modbus TCP.") {
  app_.set_version_flag("--version", std::string("bezcam ") + kVersion);
  app_.require_subcommand(1);
  // --help shows every option's default (timeouts, buffer, retries...).
  app_.option_defaults()->always_capture_default(true);
  const auto add = [this](CLI::App* sub, std::function<int()> run) { subcommands_.push_back({sub, std::move(run)}); };
  add(setup_check(app_, args_.check), [this] { return run_check(args_.check); });
  add(setup_convert(app_, args_.convert), [this] { return run_convert(args_.convert); });
  add(setup_import(app_, args_.import_drawing), [this] { return run_import(args_.import_drawing); });
  add(setup_lint(app_, args_.lint), [this] { return run_lint(args_.lint); });
  add(setup_preview(app_, args_.preview), [this] { return run_preview(args_.preview); });
  add(setup_sheet(app_, args_.sheet), [this] { return run_sheet(args_.sheet); });
  add(setup_simulate(app_, args_.simulate), [this] { return run_simulate(args_.simulate); });
  add(setup_status(app_, args_.status), [this] { return run_status(args_.status); });
  add(setup_stream(app_, args_.stream), [this] { return run_stream(args_.stream); });
  add(setup_verify(app_, args_.verify), [this] { return run_verify(args_.verify); });
  add_help_examples(app_);
}

void CommandLine::parse(const std::vector<std::string>& argv) {
  argv_ = argv;
  std::vector<const char*> c_argv;
  for (const auto& a : argv) c_argv.push_back(a.c_str());
  app_.parse(static_cast<int>(c_argv.size()), c_argv.data());
}

const CLI::App* CommandLine::chosen() const {
  for (const auto& s : subcommands_)
    if (s.app->parsed()) return s.app;
  return nullptr;
}

int CommandLine::run() const {
  for (const auto& s : subcommands_)
    if (s.app->parsed()) return s.run();
  return exit_status::invalid;
}

namespace {

// For `--tol 0.1`: the option of the command the user most likely meant (a
// unique prefix, or within a few edits), or "".
std::string option_meant(const CLI::App& cmd, const std::string& given) {
  const std::string name = given.substr(0, given.find('='));
  std::vector<std::string> longs;
  for (const CLI::Option* opt : cmd.get_options())
    for (const auto& l : opt->get_lnames()) longs.push_back("--" + l);
  std::vector<std::string> prefixed;
  for (const auto& l : longs)
    if (l.rfind(name, 0) == 0) prefixed.push_back(l);
  if (prefixed.size() == 1) return prefixed.front();
  std::vector<std::string_view> known(longs.begin(), longs.end());
  return resembled_key(name, known).value_or("");
}

// The library names the settings a caller passed (Place::setting); the
// program shows them as the options they came from.
Error as_shown(const Error& e) {
  static const std::pair<const char*, const char*> flags[] = {
      {"output", "--output"}, {"tolerance", "--tolerance"}, {"deviation", "--deviation"}};
  const auto& place = e.place();
  if (place.setting && !place.option) {
    for (const auto& [setting, flag] : flags)
      if (*place.setting == setting) return e.with_option(flag);
    // A drawing's import settings (import/drawing.hpp): --set KEY, --layer.
    if (*place.setting == "layers") return e.with_option("--layer");
    if (*place.setting == "drawing_units") return e.with_option("--units");
    if (*place.setting == "only" || *place.setting == "skip") return e.with_option("--" + *place.setting);
    if (place.setting->rfind("settings.", 0) == 0) return e.with_option("--set " + place.setting->substr(9));
  }
  return e;
}

// A refusal on stderr: its sentence and id, then the independent refusals
// of the same input, each with its place.
void print_refusal(const Error& e) {
  std::cerr << "bezcam: error: " << e.what() << "\n  (error id: " << e.id() << ")\n";
  constexpr size_t kShown = 20;
  for (size_t i = 0; i < e.more().size() && i < kShown; ++i)
    std::cerr << "bezcam: error: " << e.more()[i].what() << "\n  (error id: " << e.more()[i].id() << ")\n";
  if (e.more().size() > kShown)
    std::cerr << "bezcam: error: ... and " << e.more().size() - kShown << " more refusals of the same input\n";
}

}  // namespace

int CommandLine::usage_error(const CLI::ParseError& e) {
  // The first argument names the command (it is an option only for the
  // program's own --help and --version).
  if (!chosen() && argv_.size() > 1 && !argv_[1].empty() && argv_[1][0] != '-') {
    const std::string& word = argv_[1];
    std::vector<std::string> names;
    for (const auto& s : subcommands_) names.push_back(s.app->get_name());
    const std::vector<std::string_view> known(names.begin(), names.end());
    const std::string meant = resembled_key(word, known).value_or("");
    std::cerr << "bezcam: error: there is no command " << word << (meant.empty() ? "" : ": did you mean " + meant + "?")
              << "\n  (bezcam --help lists the commands)\n";
    return exit_status::invalid;
  }
  if (dynamic_cast<const CLI::ExtrasError*>(&e)) {
    for (const auto& s : subcommands_) {
      if (!s.app->parsed()) continue;
      for (const auto& extra : s.app->remaining()) {
        if (extra.size() < 2 || extra[0] != '-') continue;
        if (const std::string meant = option_meant(*s.app, extra); !meant.empty()) {
          const std::string& name = s.app->get_name();
          std::cerr << "bezcam: error: " << name << " has no option " << extra.substr(0, extra.find('='))
                    << ": did you mean " << meant << "?\n  (bezcam " << name << " --help lists its options)\n";
          return exit_status::invalid;
        }
      }
    }
  }
  // Usage errors read like every other refusal: one sentence, then how
  // to find the right form.
  std::cerr << "bezcam: error: " << e.what()
            << "\n  (bezcam --help lists the commands, bezcam COMMAND --help their options)\n";
  return exit_status::invalid;
}

int run_command_line(const std::vector<std::string>& argv) {
  CommandLine command_line;
  try {
    command_line.parse(argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return command_line.app().exit(e);  // --help, --version
    return command_line.usage_error(e);
  }
  try {
    return command_line.run();
  } catch (const Error& error) {
    const Error e = as_shown(error);
    print_refusal(e);
    return exit_status_of(e.family());
  } catch (const std::bad_alloc&) {
    std::cerr << "bezcam: error: out of memory; the input is too large for this machine\n";
    return exit_status::io;
  } catch (const std::exception& e) {
    std::cerr << "bezcam: internal error: " << e.what() << "\n  (please report this with the input file)\n";
    return exit_status::internal;
  }
}

}  // namespace bezcam::cli

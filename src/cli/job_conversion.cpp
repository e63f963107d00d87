#include "job_conversion.hpp"

#include "bezcam/error.hpp"
#include "job_input.hpp"
#include "profiles.hpp"
#include "progress.hpp"

namespace bezcam::cli {

JobConversion convert_job_file(const std::string& path, const ConversionOptions& conv, const PostOptions& post,
                               bool quiet, const char* command) {
  JobConversion c{read_job(path, conv), {}, {}, {}, {}};
  try {
    c.machine = resolve_profile(c.job, conv.machine);
  } catch (const Error&) {
    if (!quiet) print_warnings(c.job.warnings);
    throw;
  }
  ConvertOptions& opt = c.options;
  const bool best = conv.output == "best";
  if (best && !c.machine.motion) {
    if (!quiet) print_warnings(c.job.warnings);
    refuse_best_without_motion(c.machine);
  }
  if (!best) opt.output = parse_output_mode(conv.output);
  if (conv.tolerance > 0) opt.tolerance = conv.tolerance;
  // Kept with the options: --compare-outputs converts the job again in
  // the other modes.
  opt.memo = make_conversion_memo();
  apply_post_options(post, c.job, c.machine, opt);
  Progress progress(command, "entities", c.job.entities.size(), progress_config(quiet));
  opt.on_entity = [&](size_t done, size_t, const std::string& label) { progress.set(done, label); };
  try {
    // Every refusal before a byte is written.
    if (best) {
      BestConversion b = convert_best(c.job, c.machine, opt);
      c.result = std::move(b.result);
      c.best = std::move(b.choice);
      opt.entity_output.assign(c.job.entities.size(), OutputMode::lines);
      for (const Entity& e : c.job.entities) opt.entity_output[e.index] = c.best->output_of(e.index);
    } else {
      c.result = convert_program(c.job, c.machine, opt);
    }
  } catch (const Error&) {
    progress.finish();
    if (!quiet) print_warnings(c.job.warnings);
    throw;
  }
  progress.finish();
  opt.on_entity = nullptr;
  c.result.program.warnings = shown_warnings(c.result.program.warnings, conv);
  refuse_warnings_if_strict(c.result.program.warnings, conv);
  return c;
}

}  // namespace bezcam::cli

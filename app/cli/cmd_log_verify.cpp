// meshstep log verify: replay forward, backward and forward again, checking every hash.
#include <cstdio>
#include <memory>

#include "cmd_log.hpp"
#include "meshstep/replay/verify.hpp"

namespace meshstep::app {
namespace {

struct VerifyArgs {
  std::string log;
  bool quiet = false;
  bool verbose = false;
};

int run_verify(const VerifyArgs& args) {
  const Verbosity verbosity = args.quiet ? Verbosity::quiet : args.verbose ? Verbosity::verbose : Verbosity::normal;
  return with_log_errors([&] {
    const replay::LogReader log(args.log);
    const char* passes[] = {"forward", "backward", "forward again"};
    int shown = -1;
    const replay::VerifyReport r = replay::verify(log, [&](int pass, double) {
      if (pass != shown) print_progress(verbosity, "verifying " + args.log + ": " + passes[pass]);
      shown = pass;
    });
    if (!r.ok) {
      print_error(args.log + ": " + r.problem);
      return kExitBadInput;
    }
    if (verbosity != Verbosity::quiet)
      std::printf("%s: ok: %llu events in %llu steps replayed forward, backward and forward again; "
                  "the mesh matched the algorithm's own at %llu keyframe visits (slot by slot and by hash)\n",
                  args.log.c_str(), static_cast<unsigned long long>(r.events),
                  static_cast<unsigned long long>(r.steps), static_cast<unsigned long long>(r.keyframes_checked));
    return kExitOk;
  });
}

}  // namespace

Command add_log_verify_command(CLI::App& log) {
  auto args = std::make_shared<VerifyArgs>();
  CLI::App* cmd = log.add_subcommand(
      "verify",
      "Replay the whole log forward, back to the start and forward again, checking every face\n"
      "write against the mesh it applies to, and the mesh against every keyframe (copies of the\n"
      "algorithm's own mesh, the last one taken at the end). Exit 0 if all match, 1 if not.");
  cmd->add_option("LOG", args->log, "Replay log")->required();
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors");
  cmd->add_flag("-v,--verbose", args->verbose, "Print progress");
  return {cmd, [args] { return run_verify(*args); }};
}

}  // namespace meshstep::app

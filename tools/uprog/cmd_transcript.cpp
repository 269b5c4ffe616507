// `uprog transcript FILE...`: replays each transcript on a fresh simulated drive, prints every
// mismatch as FILE:LINE: expected …, got …, and exits 0 only if all of them match.
#include <fmt/core.h>

#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "dialect_choice.h"
#include "dialects/registry.h"
#include "transcript/transcript.h"

namespace uprog::cli {
namespace {

void add_transcript(Options& cmd, Action& action) {
  auto files = std::make_shared<std::vector<std::string>>();
  auto quiet = std::make_shared<bool>(false);
  auto dialect_name = std::make_shared<std::string>();
  cmd.option("FILE", *files, "transcript files (docs/transcripts.md)").required();
  cmd.flag("-q,--quiet", *quiet, "print only mismatches");
  cmd.option("--dialect", *dialect_name,
             "the dialect of transcripts without a `dialect` line (default: `uprog dialects` lists "
             "it first)");
  cmd.on_chosen([&action, files, quiet, dialect_name] {
    action = [files, quiet, dialect_name] {
      const dialect::Dialect* d = &dialects::default_dialect();
      if (!dialect_name->empty() &&
          (d = choose_dialect(*dialect_name, "", "transcript")) == nullptr)
        return 2;
      int failed = 0, checks = 0;
      for (const std::string& path : *files) {
        const transcript::TranscriptResult r = transcript::run_transcript_file(path, {}, d);
        checks += r.checks;
        for (const std::string& f : r.failures) fmt::print("{}\n", f);
        if (!r.ok) ++failed;
        if (!*quiet) fmt::print("{}: {} ({} checks)\n", path, r.ok ? "ok" : "FAILED", r.checks);
      }
      fmt::print("{} of {} transcripts passed, {} checks\n",
                 files->size() - static_cast<size_t>(failed), files->size(), checks);
      return failed == 0 ? 0 : 1;
    };
  });
}

const Subcommand kTranscript("transcript",
                             "Replay transcripts on a simulated drive and check the answers",
                             add_transcript);

}  // namespace
}  // namespace uprog::cli

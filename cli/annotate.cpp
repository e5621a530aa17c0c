// villa annotate DIR: label, filter and describe the partitioner's layouts (the paper's human-in-the-loop
// annotation), or in batch: --status, --auto, --export FILE.jsonl; work packages for several people:
// --split N, --merge PKG..., --review.
#include <filesystem>
#include <iostream>
#include <memory>

#include "annotator/packages.h"
#include "annotator/session.h"
#include "annotator/status_report.h"
#include "annotator/tui.h"
#include "cli/command.h"
#include "cli/flags.h"
#include "util/atomic_file.h"

namespace {

struct AnnotateArgs {
  std::string dir;
  bool status = false;
  bool automatic = false;
  std::string export_path;
  bool force = false;
  bool ascii = false;
  std::string id;
  std::string annotator;
  std::string filter = "all";
  bool review = false;
  int split = 0;
  double overlap = 0.1;
  std::vector<std::string> merge;
};

int Annotate(const AnnotateArgs& args) {
  using namespace villa::annotator;
  bool batch = args.status || args.automatic || !args.export_path.empty() || args.split > 0 || !args.merge.empty();
  bool interactive = !batch;
  if (args.review && batch) throw villa::cli::UsageError("--review is the interactive tool: leave out --status, --auto, --export, --split and --merge");
  auto filter = ParseFilter(args.filter);
  if (!filter) {
    std::string names;
    for (Filter f : kAllFilters) names += (names.empty() ? "" : ", ") + std::string(FilterName(f));
    throw villa::cli::UsageError("--filter: \"" + args.filter.substr(0, 40) + "\" is none of " + names);
  }
  SessionOptions options;
  // --status, --split and a lone --export only read: they never touch the journal.
  options.writable = interactive || args.automatic || !args.merge.empty();
  options.annotator = args.annotator.empty() ? LoginName() : args.annotator;
  if (villa::Status name = CheckAnnotatorName(options.annotator); !name) {
    if (!args.annotator.empty()) throw villa::cli::UsageError(name.error());
    options.annotator = "unknown";  // a login name we cannot use: say nothing, label the work "unknown"
  }
  if (args.split > 0) {
    SplitOptions probe;
    probe.parts = args.split;
    probe.overlap = args.overlap;
    if (std::string why = probe.Invalid(); !why.empty()) throw villa::cli::UsageError(why);
  }
  auto opened = Session::Open(args.dir, options);
  if (!opened) {
    std::cerr << "villa annotate: " << opened.error() << "\n";
    return villa::cli::kExitFailure;
  }
  Session& session = **opened;
  for (const std::string& warning : session.warnings()) std::cerr << "villa annotate: warning: " << warning << "\n";

  if (interactive) {
    TuiOptions tui;
    tui.ascii = args.ascii;
    tui.start_id = args.id;
    tui.filter = *filter;
    tui.review = args.review;
    return RunAnnotatorTui(session, tui);
  }
  std::error_code ec;
  if (!args.export_path.empty() && std::filesystem::exists(args.export_path, ec)) {
    // The export is written beside its target and renamed over it: a device, a pipe or a folder would
    // be replaced by a plain file (--export /dev/null --force once did exactly that), so only files.
    if (!std::filesystem::is_regular_file(args.export_path, ec)) {
      std::cerr << "villa annotate: " << args.export_path << ": exists and is not a plain file (export writes a file)\n";
      return villa::cli::kExitFailure;
    }
    if (!args.force) {
      std::cerr << "villa annotate: " << args.export_path << ": exists (use --force to overwrite)\n";
      return villa::cli::kExitFailure;
    }
  }
  if (!args.merge.empty()) {
    std::vector<std::filesystem::path> packages(args.merge.begin(), args.merge.end());
    auto merged = MergePackages(session, packages);
    if (!merged) {
      std::cerr << "villa annotate: " << merged.error() << "\n";
      return villa::cli::kExitFailure;
    }
    std::cout << merged->Brief() << "\n";
  }
  if (args.automatic) {
    auto made = session.AutoAnnotate();
    if (!made) {
      std::cerr << "villa annotate: " << made.error() << "\n";
      return villa::cli::kExitFailure;
    }
    std::cout << "auto-annotated " << made->total() << " pending layouts: " << made->automatic << " auto, "
              << made->rejected << " rejected by the rules (none verified: no person looked at them)\n";
  }
  if (args.split > 0) {
    SplitOptions split;
    split.parts = args.split;
    split.overlap = args.overlap;
    auto made = SplitIntoPackages(session, split);
    if (!made) {
      std::cerr << "villa annotate: " << made.error() << "\n";
      return villa::cli::kExitFailure;
    }
    std::cout << made->Brief() << "\n"
              << "each person: villa annotate " << (made->folder / made->packages.front()).string()
              << " --annotator NAME; then: villa annotate " << args.dir << " --merge " << made->folder.string()
              << "/part-*\n";
  }
  if (!args.export_path.empty()) {
    villa::Status written = villa::WriteFileAtomic(args.export_path, session.ExportJsonl());
    if (!written) {
      std::cerr << "villa annotate: " << written.error() << "\n";
      return villa::cli::kExitFailure;
    }
    std::cout << "exported " << session.size() << " records to " << args.export_path << "\n";
  }
  if (args.status) std::cout << StatusReport(session);
  return villa::cli::kExitOk;
}

villa::cli::Registration registration{40, [](CLI::App& app) {
  auto args = std::make_shared<AnnotateArgs>();
  CLI::App* sub = app.add_subcommand(
      "annotate",
      "Label, filter and describe a dataset's layouts in the terminal (or --auto / --export / --status; "
      "--split / --merge / --review for several annotators)");
  sub->add_option("DIR", args->dir, "dataset folder from `villa synth` (holds layouts.jsonl)")->required();
  sub->add_flag("--status", args->status,
                "print progress, who labelled how much, and the agreement on layouts labelled twice; then exit");
  sub->add_flag("--auto", args->automatic,
                "give every pending layout its drafted labels, fixes and descriptions, marked auto (never verified)");
  sub->add_option("--export", args->export_path,
                  "write the current state, one JSON record a line (id, status, reason, descriptions, annotation, layout)");
  sub->add_flag("--force", args->force, "let --export overwrite an existing file");
  sub->add_flag("--ascii", args->ascii, "draw with plain ASCII instead of box-drawing characters");
  sub->add_option("--id", args->id, "open this layout first (an id, its last digits, or #position)");
  sub->add_option("--annotator", args->annotator, "your name in the journal and the export (default: the login name)");
  sub->add_option("--filter", args->filter,
                  "step through these layouts only: all, to-do, pending, auto, rejected, verified, decided, disagreements");
  sub->add_flag("--review", args->review,
                "review who did what: starts on the layouts two people decided differently (else those decided)");
  sub->add_option("--split", args->split,
                  "write N work packages to DIR/packages/part-K-of-N (the layouts no person decided yet)")
      ->transform(villa::cli::WholeIn(2, 1000));
  sub->add_option("--overlap", args->overlap,
                  "with --split: share of layouts put in two packages, to measure agreement (0 to 0.5, default 0.1)")
      ->check(villa::cli::NumberIn(0.0, 0.5));
  sub->add_option("--merge", args->merge, "merge these work packages' journals into DIR's journal")->expected(1, -1);
  sub->callback([args] { villa::cli::SetExitCode(Annotate(*args)); });
}};

}  // namespace

// villa annotate DIR: label, filter and describe the partitioner's layouts (the paper's human-in-the-loop
// annotation), or in batch: --status, --auto, --export FILE.jsonl.
#include <filesystem>
#include <iostream>
#include <memory>

#include "annotator/session.h"
#include "annotator/tui.h"
#include "cli/command.h"
#include "util/atomic_file.h"
#include "util/text_table.h"

namespace {

struct AnnotateArgs {
  std::string dir;
  bool status = false;
  bool automatic = false;
  std::string export_path;
  bool force = false;
  bool ascii = false;
  std::string id;
};

int Annotate(const AnnotateArgs& args) {
  using namespace villa::annotator;
  bool interactive = !args.status && !args.automatic && args.export_path.empty();
  // --status and a lone --export only read: they never touch the journal.
  bool writable = interactive || args.automatic;
  auto opened = Session::Open(args.dir, writable);
  if (!opened) {
    std::cerr << "villa annotate: " << opened.error() << "\n";
    return villa::cli::kExitFailure;
  }
  Session& session = **opened;
  for (const std::string& warning : session.warnings()) std::cerr << "villa annotate: warning: " << warning << "\n";

  if (interactive) {
    TuiOptions options;
    options.ascii = args.ascii;
    options.start_id = args.id;
    return RunAnnotatorTui(session, options);
  }
  std::error_code ec;
  if (!args.export_path.empty() && std::filesystem::exists(args.export_path, ec) && !args.force) {
    std::cerr << "villa annotate: " << args.export_path << ": exists (use --force to overwrite)\n";
    return villa::cli::kExitFailure;
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
  if (!args.export_path.empty()) {
    villa::Status written = villa::WriteFileAtomic(args.export_path, session.ExportJsonl());
    if (!written) {
      std::cerr << "villa annotate: " << written.error() << "\n";
      return villa::cli::kExitFailure;
    }
    std::cout << "exported " << session.size() << " records to " << args.export_path << "\n";
  }
  if (args.status) {
    Counts c = session.counts();
    villa::TextTable table({"status", "layouts", "share"});
    table.AddRow({"verified", std::to_string(c.verified), villa::FormatPercent(c.verified, c.total())});
    table.AddRow({"auto", std::to_string(c.automatic), villa::FormatPercent(c.automatic, c.total())});
    table.AddRow({"rejected", std::to_string(c.rejected), villa::FormatPercent(c.rejected, c.total())});
    table.AddRow({"pending", std::to_string(c.pending), villa::FormatPercent(c.pending, c.total())});
    table.AddRow({"total", std::to_string(c.total()), villa::FormatPercent(c.total(), c.total())});
    std::cout << args.dir << ": " << c.total() - c.pending << " of " << c.total() << " layouts annotated\n"
              << table.Render();
    int next = session.NextPending(0);
    if (next >= 0) std::cout << "next pending: " << session.record(next).id << "\n";
  }
  return villa::cli::kExitOk;
}

villa::cli::Registration registration{40, [](CLI::App& app) {
  auto args = std::make_shared<AnnotateArgs>();
  CLI::App* sub = app.add_subcommand(
      "annotate", "Label, filter and describe a dataset's layouts in the terminal (or --auto / --export / --status)");
  sub->add_option("DIR", args->dir, "dataset folder from `villa synth` (holds layouts.jsonl)")->required();
  sub->add_flag("--status", args->status, "print progress (verified / auto / rejected / pending) and exit");
  sub->add_flag("--auto", args->automatic,
                "give every pending layout its drafted labels, fixes and descriptions, marked auto (never verified)");
  sub->add_option("--export", args->export_path,
                  "write the current state, one JSON record a line (id, status, reason, descriptions, layout)");
  sub->add_flag("--force", args->force, "let --export overwrite an existing file");
  sub->add_flag("--ascii", args->ascii, "draw with plain ASCII instead of box-drawing characters");
  sub->add_option("--id", args->id, "open this layout first instead of the first pending one");
  sub->callback([args] { villa::cli::SetExitCode(Annotate(*args)); });
}};

}  // namespace

// villa render FILE -o plan.png|plan.svg: floor-plan pictures of a layout.
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "cli/command.h"
#include "cli/flags.h"
#include "layout/layout_io.h"
#include "render/plan_render.h"

namespace villa::cli {
namespace {

struct RenderCommand {
  std::string input;
  std::string output;
  int line = 0;  // JSONL record: line number (1-based); 0 = the first record
  bool force = false;
  PlanRenderOptions options;
};

Result<Layout> ReadInput(const RenderCommand& command) {
  const std::filesystem::path path = command.input;
  if (path.extension() != ".jsonl") {
    if (command.line > 0) throw UsageError("render: --line applies to a .jsonl stream, not " + command.input);
    return LoadLayout(path);
  }
  std::optional<Result<Layout>> found;
  Status read = ReadJsonl(path, [&](const Json& record, int line) {
    if (command.line > 0 && line != command.line) return true;
    found = LayoutFromRecord(record, command.input + ":" + std::to_string(line));
    return false;
  });
  if (!read.ok()) return Error{read.error()};
  if (!found) {
    return Error{command.input + (command.line > 0 ? ": no record on line " + std::to_string(command.line)
                                                   : std::string(": no record"))};
  }
  return *found;
}

void Run(RenderCommand& command) {
  const std::filesystem::path out = command.output;
  std::string extension = out.extension().string();
  for (char& ch : extension) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (extension != ".png" && extension != ".svg") {
    throw UsageError("render: " + command.output + ": unknown picture type '" + out.extension().string() +
                     "' (the extension must be .png or .svg)");
  }
  if (!std::filesystem::exists(command.input)) throw UsageError("render: " + command.input + ": no such file");
  if (std::filesystem::exists(out) && !command.force) {
    throw UsageError("render: " + command.output + " exists; pass --force to overwrite it");
  }
  if (std::string problem = command.options.Check(); !problem.empty()) throw UsageError("render: " + problem);

  Result<Layout> layout = ReadInput(command);
  if (!layout.ok()) {
    std::cerr << "villa render: " << layout.error() << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  if (command.options.source_name.empty()) {
    command.options.source_name = std::filesystem::path(command.input).filename().string();
    if (command.line > 0) command.options.source_name += ":" + std::to_string(command.line);
  }
  Status status = RenderPlan(*layout, out, command.options);
  if (!status.ok()) {
    std::cerr << "villa render: " << status.error() << "\n";
    SetExitCode(kExitFailure);
    return;
  }
  std::cout << command.output << "\n";
  SetExitCode(kExitOk);
}

Registration registration{30, [](CLI::App& app) {
  auto command = std::make_shared<RenderCommand>();
  CLI::App* sub = app.add_subcommand(
      "render",
      "Draw the floor plans of a layout: one panel per floor, rooms coloured by category with name and\n"
      "area, walls, doors with their swing, opens, windows (panoramic in blue), the entrance arrow, the\n"
      "staircase, a scale bar and a legend. Invalid layouts are drawn too; elements that are not on a\n"
      "wall where the format puts them are red. Exit status: 0 written, 1 unreadable layout or write\n"
      "failure, 2 usage.");
  sub->add_option("file", command->input, "layout (.json), or a JSONL stream (.jsonl) with --line")->required();
  sub->add_option("-o,--output", command->output, "picture to write: .png or .svg (written atomically)")->required()->check(PathName());
  sub->add_option("--line", command->line, "for a .jsonl stream: the line of the record to draw (default: the first)")
      ->transform(WholeIn(1, std::numeric_limits<int>::max()));
  sub->add_flag("-f,--force", command->force, "overwrite the output file when it exists");
  auto* scale = sub->add_option("--scale", command->options.pixels_per_metre, "pixels per metre (5..400; default 40)")
                    ->check(NumberIn(5.0, 400.0));
  sub->add_option("--width", command->options.target_width_px,
                  "total picture width in px; the scale is chosen to fill it")
      ->transform(WholeIn(1, 30000))
      ->excludes(scale);
  sub->add_option("--levels", command->options.levels, "levels to draw, e.g. --levels 0,2 (default: all)")
      ->delimiter(',')
      ->transform(WholeIn(0, 999));
  sub->add_option("--title", command->options.title, "title line (default: file name, floors, rooms, total area)");
  sub->add_option("--font", command->options.font_family, "font family (default \"DejaVu Sans\")");
  sub->add_option("--font-size", command->options.font_size_px, "size of room names in px (6..48; default 13)")
      ->check(NumberIn(6.0, 48.0));
  sub->add_flag_callback("--no-legend", [command] { command->options.legend = false; },
                         "leave out the legend and the scale bar");
  sub->callback([command] { Run(*command); });
}};

}  // namespace
}  // namespace villa::cli

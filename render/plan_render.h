#pragma once
// Floor-plan pictures of a layout: one panel per level side by side, all at one scale, rooms filled by
// category colour and labelled with their name and area, walls, doors with their swing, opens, windows,
// the entrance arrow, the staircase, a scale bar, a legend and a title line.
//
// Invalid layouts render too (that is when a picture helps most): whatever is there is drawn, and a
// 1D element that does not lie where FORMAT.md rule 3 puts it (a door or open off the shared boundary
// of two rooms, a window or entrance off the exterior boundary, an interior wall between no two rooms)
// is drawn in red.
//
// Units: lengths in the plan are metres; everything in these options is in pixels of the output
// (SVG user units are the same pixels).
#include <filesystem>
#include <string>
#include <vector>

#include "layout/layout.h"
#include "render/palette.h"
#include "util/result.h"

namespace villa {

struct PlanRenderOptions {
  // Scale of the plans, px per metre. Used when target_width_px is 0. Range 5..400.
  double pixels_per_metre = 40.0;
  // When > 0, the whole picture is this many px wide and the scale is chosen to fill it (the result
  // may be wider when the title or legend need more room than the plans leave).
  int target_width_px = 0;
  // White space around the whole picture, px.
  double margin_px = 28.0;
  // Space between two level panels, px.
  double panel_gap_px = 40.0;
  // Draw the legend (categories present and the symbols used) and the scale bar under the panels.
  bool legend = true;
  // The title line. Empty: "<source_name>  ·  3 floors  ·  14 rooms  ·  312.5 m²" made from the layout.
  std::string title;
  // The name shown in the generated title (usually the layout's file name); empty: "Floor plan".
  std::string source_name;
  // Levels to draw (0 = ground floor), in the order given; empty: every level of the layout.
  std::vector<int> levels;
  // Font family for every text (cairo "toy" font selection, fontconfig name).
  std::string font_family = "DejaVu Sans";
  // Size of the room names, px; areas, headings and the legend scale with it. Labels shrink (down to
  // about half) to fit small rooms. Range 6..48.
  double font_size_px = 13.0;
  // zlib level of PNG output, 1..9: 3 encodes about 2.5 times faster than 6 for files about a quarter
  // larger (a three-floor plan: ~20 ms, ~100 kB).
  int png_compression = 3;
  // Neither side of the picture may exceed this (cairo's limit is 32767); a layout so large that the
  // chosen scale would exceed it is drawn at a smaller scale instead.
  int max_side_px = 16000;

  // An empty string when the options are usable, else what is wrong ("pixels_per_metre = 0: ...").
  std::string Check() const;
};

// What a furnished plan draws over the rooms, in plan metres: furniture footprints (`villa furnish`,
// `villa generate`) and walking paths (reachability). Shapes go over the room fills and under the walls,
// doors and labels, in the order given (floor objects first, so what stands on them shows on top); paths
// go over the doors.
struct PlanOverlay {
  struct Shape {
    int level = 0;
    Ring outline;           // plan m, either winding, at least 3 points
    Rgb fill;               // sRGB
    double fill_alpha = 1.0;
    Rgb ink;                // the outline's colour
  };
  struct Path {
    int level = 0;
    std::vector<Point> points;  // plan m, at least 2
    Rgb color;
    double width_px = 1.6;      // thin: it must not hide the furniture under it
  };
  std::vector<Shape> shapes;
  std::vector<Path> paths;
  bool empty() const { return shapes.empty() && paths.empty(); }
};

// Picks PNG (.png) or SVG (.svg) by the extension of `out` (case-insensitive); any other extension is
// an error naming the file. The picture is made in memory and written atomically (temporary beside it,
// then renamed): an existing file is replaced whole; callers that must not overwrite check first (the
// `villa render` command asks for --force).
Status RenderPlan(const Layout& layout, const std::filesystem::path& out, const PlanRenderOptions& options = {});

// The picture as the bytes of a PNG file (8-bit RGB(A)), for callers that embed a preview.
Result<std::string> RenderPlanPng(const Layout& layout, const PlanRenderOptions& options = {});

// The picture as SVG text (UTF-8). Room names, areas and all other words are real <text> elements;
// each room is a <g> whose <title> is its JSON name ("kitchen_0/0").
Result<std::string> RenderPlanSvg(const Layout& layout, const PlanRenderOptions& options = {});

// The same pictures with an overlay drawn on them; the legend names "Furniture" and "Walking path" when
// the overlay has them. Shapes and paths on a level without a panel are not drawn.
Result<std::string> RenderPlanPng(const Layout& layout, const PlanOverlay& overlay, const PlanRenderOptions& options = {});
Result<std::string> RenderPlanSvg(const Layout& layout, const PlanOverlay& overlay, const PlanRenderOptions& options = {});

// Where things land in the picture, for callers that annotate it or test it.
struct PlanFrame {
  int width_px = 0;
  int height_px = 0;
  double pixels_per_metre = 0.0;
  struct Panel {
    int level = 0;
    double plan_left_px = 0.0;  // pixel x of plan x = min_x of the layout's bounding box
    double plan_top_px = 0.0;   // pixel y of plan y = max_y (the plan's y axis points up, pixels down)
  };
  std::vector<Panel> panels;
  double min_x = 0.0;  // bounding box of every level's rooms, m
  double max_y = 0.0;

  // Pixel position (x right, y down) of plan point `p` on the panel of `level`; {-1, -1} when that
  // level has no panel.
  Point ToPixel(int level, Point p) const;
};

// The frame RenderPlanPng / RenderPlanSvg use for these arguments.
Result<PlanFrame> ComputePlanFrame(const Layout& layout, const PlanRenderOptions& options = {});

// A point well inside a room polygon, where its label goes: the pole of inaccessibility (the interior
// point farthest from the boundary), so an L-shaped room gets a point inside its widest part rather
// than a centroid that may lie outside. Accurate to `precision` m.
Point RoomLabelPoint(const Ring& polygon, double precision = 0.01);

}  // namespace villa

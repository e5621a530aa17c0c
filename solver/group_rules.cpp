#include "solver/group_rules.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesh/geometry2d.h"
#include "util/text_table.h"

namespace villa::solver {

double AngleDegrees(Point a, Point b) {
  const double la = geo::Len(a), lb = geo::Len(b);
  if (la <= 0.0 || lb <= 0.0) return 180.0;
  return std::acos(std::clamp(geo::Dot(a, b) / (la * lb), -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

std::string TableSeatProblem(const OrientedBox& chair, const OrientedBox& table) {
  const Point l = table.Local(chair.c);
  Point inward;
  if (std::abs(l.x) <= table.hx && std::abs(l.y) > table.hy) inward = l.y > 0 ? geo::Scale(table.V(), -1.0) : table.V();
  else if (std::abs(l.y) <= table.hy && std::abs(l.x) > table.hx) inward = l.x > 0 ? geo::Scale(table.U(), -1.0) : table.U();
  else return "not beside a side of the table (at a corner or beyond its ends)";
  const double gap = PlanGap(chair, table);
  if (gap > kSeatToTable) return FormatFixed(gap, 2) + " m from the table (<= " + FormatFixed(kSeatToTable, 2) + ")";
  if (const double a = AngleDegrees(chair.Front(), inward); a > kSeatFacing)
    return "turned " + FormatFixed(a, 0) + " degrees from the table (<= " + FormatFixed(kSeatFacing, 0) + ")";
  return "";
}

std::string DeskSeatProblem(const OrientedBox& chair, const OrientedBox& desk) {
  const Point l = desk.Local(chair.c);
  if (l.y >= -desk.hy || std::abs(l.x) > desk.hx + 0.1) return "not before the desk";
  if (const double gap = PlanGap(chair, desk); gap > kDeskSeatGap)
    return FormatFixed(gap, 2) + " m from the desk (<= " + FormatFixed(kDeskSeatGap, 2) + ")";
  if (const double a = AngleDegrees(chair.Front(), desk.V()); a > kDeskSeatFacing)
    return "turned " + FormatFixed(a, 0) + " degrees from the desk (<= " + FormatFixed(kDeskSeatFacing, 0) + ")";
  return "";
}

std::string BedsideProblem(const OrientedBox& nightstand, const OrientedBox& bed) {
  const Point l = bed.Local(nightstand.c);
  if (std::abs(l.x) <= bed.hx) return "at the bed's " + std::string(l.y > 0 ? "head" : "foot") + " end, not beside it";
  if (const double gap = PlanGap(nightstand, bed); gap > kBedsideGap)
    return FormatFixed(gap, 2) + " m off the bed's side (<= " + FormatFixed(kBedsideGap, 2) + ")";
  if (const double from_head = bed.hy - l.y; from_head > kBedsideHead)
    return FormatFixed(from_head, 2) + " m from the head's line (<= " + FormatFixed(kBedsideHead, 2) + "): not at the head";
  return "";
}

std::string PillowProblem(Point pillow, const OrientedBox& bed) {
  const double from_head = bed.hy - bed.Local(pillow).y;
  if (from_head > kPillowHead * 2.0 * bed.hy) return FormatFixed(from_head, 2) + " m from the head (mid-bed)";
  return "";
}

OrientedBox MattressBox(const OrientedBox& bed, const AssetRecord* asset, double scale) {
  OrientedBox box = bed;
  if (!asset || asset->support_surfaces.empty()) return box;
  const SupportSurface* top = &asset->support_surfaces.front();
  for (const SupportSurface& f : asset->support_surfaces)
    if (f.z > top->z) top = &f;
  if (top->polygon.size() < 3) return box;
  double y0 = 1e300, y1 = -1e300;
  for (const Point& q : top->polygon) y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  box.c = geo::Add(box.c, geo::Scale(box.V(), 0.5 * (y0 + y1) * scale));
  box.hy = 0.5 * (y1 - y0) * scale;
  return box;
}

std::string TvProblem(const OrientedBox& sofa, const OrientedBox& tv) {
  const double angle = AngleDegrees(sofa.Front(), geo::Sub(tv.c, sofa.c));
  if (angle > kTvAngle) return "the sofa is turned " + FormatFixed(angle, 0) + " degrees from the TV (<= " + FormatFixed(kTvAngle, 0) + ")";
  const double dist = geo::Dist(tv.c, sofa.c);
  if (dist < kTvMin || dist > kTvMax)
    return "the TV is " + FormatFixed(dist, 2) + " m from the sofa (" + FormatFixed(kTvMin, 1) + "-" + FormatFixed(kTvMax, 1) + ")";
  const double screen = AngleDegrees(tv.Front(), geo::Sub(sofa.c, tv.c));
  if (screen > kScreenFacing)
    return "the TV is turned " + FormatFixed(screen, 0) + " degrees from the sofa (<= " + FormatFixed(kScreenFacing, 0) + ")";
  return "";
}

std::string CoffeeTableProblem(const OrientedBox& table, const OrientedBox& sofa) {
  const Point l = sofa.Local(table.c);
  if (l.y > -sofa.hy || std::abs(l.x) > sofa.hx) return "the coffee table is not in front of the sofa";
  const double gap = PlanGap(sofa, table);
  if (gap < kCoffeeMin || gap > kCoffeeMax)
    return "the coffee table is " + FormatFixed(gap, 2) + " m from the sofa (" + FormatFixed(kCoffeeMin, 2) + "-" + FormatFixed(kCoffeeMax, 1) + ")";
  return "";
}

std::string SideTableProblem(const OrientedBox& side_table, const OrientedBox& sofa) {
  const Point l = sofa.Local(side_table.c);
  if (std::abs(l.x) <= sofa.hx) return "not at an end of the sofa";
  if (const double gap = PlanGap(side_table, sofa); gap > kSideTableGap)
    return FormatFixed(gap, 2) + " m from the sofa's end (<= " + FormatFixed(kSideTableGap, 2) + ")";
  return "";
}

std::string ArmchairProblem(const OrientedBox& armchair, Point focus) {
  if (const double d = geo::Dist(armchair.c, focus); d > kArmchairReach)
    return FormatFixed(d, 2) + " m from the group (<= " + FormatFixed(kArmchairReach, 1) + ")";
  if (const double a = AngleDegrees(armchair.Front(), geo::Sub(focus, armchair.c)); a > kArmchairFacing)
    return "turned " + FormatFixed(a, 0) + " degrees from the group (<= " + FormatFixed(kArmchairFacing, 0) + ")";
  return "";
}

}  // namespace villa::solver

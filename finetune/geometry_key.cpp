#include "finetune/geometry_key.h"

#include <algorithm>
#include <utility>

#include "layout/shape_codec.h"
#include "util/hash.h"

namespace villa {
namespace {

std::string SegmentText(const Segment& s) {
  Segment ordered = s;
  Point a{RoundToFormat(s.a.x), RoundToFormat(s.a.y)};
  Point b{RoundToFormat(s.b.x), RoundToFormat(s.b.y)};
  if (b.x < a.x || (b.x == a.x && b.y < a.y)) std::swap(a, b);
  ordered = {a, b};
  return FormatLineShape(ordered);
}

}  // namespace

std::string GeometryKey(const Layout& layout) {
  std::vector<std::string> parts;
  for (const auto& room : layout.rooms) {
    parts.push_back("room " + std::to_string(room.level) + " " + FormatPolygonShape(room.polygon));
  }
  for (ElementKind kind : kAllElementKinds) {
    for (const auto& e : layout.elements(kind)) {
      std::string part = std::string(ElementKindKey(kind)) + " " + std::to_string(e.level) + " " + SegmentText(e.shape);
      if (kind == ElementKind::kWindow) part += e.panoramic ? " panoramic" : " plain";
      parts.push_back(std::move(part));
    }
  }
  std::sort(parts.begin(), parts.end());
  std::string key;
  for (const auto& part : parts) {
    key += part;
    key += '\n';
  }
  return key;
}

std::uint64_t StableHash(std::string_view text) { return SplitMix64Hash(Fnv1a64(text)); }

}  // namespace villa

#pragma once
// What makes two layouts "the same" for the fine-tune export.
//   GeometryKey: the layout's geometry as text, independent of names and labels: every room polygon and
//   every 1D element (kind, level, segment with its endpoints ordered, panoramic flag), in canonical
//   shapely strings, sorted. Two layouts with equal keys differ at most in names and room categories; the
//   export keeps one of them, and splits are decided by the key's hash, so nothing of one geometry can
//   land in two splits.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "layout/layout.h"

namespace villa {

std::string GeometryKey(const Layout& layout);

// 64-bit FNV-1a of `text`, finished with the SplitMix64 mixer (util/hash.h): stable across machines and
// standard libraries (std::hash is not), so splits are the same everywhere.
std::uint64_t StableHash(std::string_view text);

}  // namespace villa

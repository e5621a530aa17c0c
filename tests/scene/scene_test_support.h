#pragma once
// Shared by the scene tests: fixture layouts built into buildings and room contexts.
#include <catch2/catch.hpp>

#include <string>

#include "building/building.h"
#include "layout/layout_io.h"
#include "scene/room_context.h"

namespace villa::scene::testing {

struct BuiltLayout {
  Layout layout;
  BuildingMesh building;
  BuildOptions options;
};

// A layout built with the default options.
inline BuiltLayout Built(Layout layout) {
  BuiltLayout out{std::move(layout), {}, {}};
  auto building = BuildBuilding(out.layout, out.options);
  REQUIRE(building.ok());
  out.building = std::move(*building);
  return out;
}

// A fixture by path relative to the source tree ("tests/fixtures/layouts/house_one_floor.json").
inline BuiltLayout LoadBuilt(const std::string& relative) {
  auto layout = LoadLayout(std::string(VILLA_SOURCE_DIR) + "/" + relative);
  REQUIRE(layout.ok());
  return Built(std::move(*layout));
}

inline RoomContext ContextOf(const BuiltLayout& b, const std::string& room) {
  auto context = RoomContextOf(b.layout, b.building, b.options, room);
  REQUIRE(context.ok());
  return std::move(*context);
}

}  // namespace villa::scene::testing

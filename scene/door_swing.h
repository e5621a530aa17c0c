#pragma once
// How each door of a level swings, as keep-out polygons (PRIORS.md clearances: the square the leaf sweeps,
// door width x door width on the leaf side, and a strip door width x 0.6 m on the other side).
//
// This is the ONE place scene/ learns door swings. Issue 10 adds the door-swing rule to layout/ (the room
// a door swings into, the hinge side, the swept square and the strip); until it lands, DoorSwings() reads
// the swing off the building's open door leaves (building.cpp hangs each leaf 90 degrees open towards the
// first side whose sweep is free of walls and stairs). When layout's function exists, DoorSwings() becomes
// a call to it and nothing else in scene/ changes.
#include <string>
#include <vector>

#include "building/building.h"
#include "layout/layout.h"

namespace villa::scene {

struct DoorSwing {
  std::string element;          // layout element name
  ElementKind kind = ElementKind::kDoor;  // kDoor or kEntrance
  Segment door;                 // the element's segment
  int side = 0;                 // the leaf opens to the left (+1) or right (-1) of door.a -> door.b; 0: closed
  int hinge = -1;               // 0: hinged at door.a, 1: at door.b, -1: closed
  Ring sweep;                   // the swept square (empty when closed), CCW
  std::vector<Ring> strips;     // width x 0.6 m beyond the wall face on the other side (both sides when closed)
};

// Every door and (on level 0) the entrance of `level`. A door the building left out (no wall under it) or
// hung closed gets strips on both sides and no sweep.
std::vector<DoorSwing> DoorSwings(const Layout& layout, const BuildingMesh& building, const BuildOptions& options,
                                  int level);

}  // namespace villa::scene

#pragma once
// A built villa as a scene of render/view3d.h: every part with its material's colour (building/materials.h),
// its level, and what a cut-away does with it (walls, door leaves, glass and stairs are cut; the roof is
// removed; slabs stay). `villa build --preview` and `villa generate` draw this scene.
#include "building/building.h"
#include "render/view3d.h"

namespace villa {

// The scene borrows the parts' meshes: `building` must outlive it.
ViewScene ViewSceneOf(const BuildingMesh& building);

}  // namespace villa

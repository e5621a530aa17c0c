#pragma once
// Pictures of one furnished room (render/view3d.h): the building's parts of the room's level around it
// (walls, door leaves, glass, stairs, the room's floor) and every placed object's asset mesh at its pose.
// The critic looks at a room through RenderRoomViews (a top view and four views from the room's corners,
// issue 14); `villa furnish` writes rooms/<room>.png with RoomPicture. Deterministic: the same room gives
// the same bytes whatever the thread count.
//
// Corner views look down at `elevation_deg` from azimuth 45, 135, 225 and 315 degrees (0 = from -y, the
// plan's south, counter-clockwise; render/view3d.h FramingCamera). Walls, door leaves and glass on the
// camera's side of the room (their centre beyond the room's centre, seen from the camera) are cut
// `cut_height` m above the floor, their cut faces filled dark, so the room shows through them while
// where they stand still reads; the other walls stand whole behind the room (with what hangs on them).
// The top view keeps every wall whole (seen from above they are thin bands). Frames: the building's
// (metres, z up); an object's pose as SCENE.md (bottom centre, yaw counter-clockwise, scale uniform).
#include <memory>
#include <string>
#include <vector>

#include "assets/asset_mesh.h"
#include "building/building.h"
#include "layout/layout.h"
#include "render/view3d.h"
#include "solver/placement.h"
#include "util/result.h"

namespace villa::solver {

struct RoomViewObject {
  std::string label;                      // written over the pictures when labels are on ("sofa-0")
  std::shared_ptr<const AssetMesh> mesh;  // asset frame; must not be null
  Pose pose;                              // world pose and uniform scale
};

struct RoomViewInput {
  const BuildingMesh* building = nullptr;  // required; outlives the call
  std::string room;                        // its floor part is drawn ("kitchen_0/0")
  int level = 0;
  Ring polygon;                            // the room's polygon (plan m, CCW): what the cameras frame
  double floor_z = 0.0;                    // m, the floor surface
  double clear_height = 2.625;             // m, floor to ceiling
  std::vector<RoomViewObject> objects;
};

struct RoomViewOptions {
  int size_px = 768;            // each view is size_px square, [64, 4096] (768: what vision models read well)
  double elevation_deg = 40.0;  // corner views' angle above the horizon, [10, 80]
  double cut_height = 0.12;     // m above the floor where the walls on the camera's side are cut, [0, 2.5]
  bool labels = false;          // object labels at the top centre of each object's box
  double label_px = 12.0;       // label font size, [6, 48]
  int samples = 1;              // rays per pixel per axis, [1, 4]
  int threads = 1;              // render threads (0: every hardware thread); rooms already run in parallel
  std::string Check() const;    // empty when usable
};

struct RoomViewImage {
  std::string name;  // "top", "corner-45", "corner-135", "corner-225", "corner-315"
  Camera camera;
  Image image;
};

// The top view, then the four corner views, in that order.
Result<std::vector<RoomViewImage>> RenderRoomViews(const RoomViewInput& room, const RoomViewOptions& options);

// The picture `villa furnish` writes for a room: its top view (no shadows: flat-lit) beside the
// view from the south-west corner (azimuth 315, sun and shadows), each `panel_px` square, 8 px apart, no
// labels.
Result<Image> RoomPicture(const RoomViewInput& room, int panel_px = 512);

}  // namespace villa::solver

#pragma once
// Pictures of one asset from four sides (render/view3d.h): what `villa assets show ID --render FILE.png`
// draws, with the record's support surfaces and cavities over the mesh (surfaces as thin coloured slabs
// at their height, cavities as see-through boxes, each labelled S<i> / C<k>), and what a multimodal
// model picks the asset's front from (assets/asset_front.h: the same views without overlays).
//
// Views look at the asset from azimuth 0, 90, 180 and 270 degrees (0 = from -y, the recorded front;
// 90 = from +x; counter-clockwise seen from above), `elevation_deg` above the horizon, each framing the
// asset's box. Asset frame as SCENE.md: metres, z up, origin at the bottom centre.
#include <string>
#include <vector>

#include "assets/asset.h"
#include "assets/asset_mesh.h"
#include "render/view3d.h"
#include "util/result.h"

namespace villa {

struct AssetViewOptions {
  int size_px = 480;            // each view is square, [64, 4096]
  double elevation_deg = 25.0;  // [0, 80]
  bool overlays = true;         // support surfaces and cavities drawn over the mesh, labelled
  int samples = 1;              // rays per pixel per axis, [1, 4]
  int threads = 0;              // 0: every hardware thread
  std::string Check() const;    // empty when usable
};

struct AssetView {
  std::string side;  // the asset's side the camera faces: "-y", "+x", "+y", "-x"
  double azimuth_deg = 0.0;
  Camera camera;
  Image image;
};

// The four views, from azimuth 0, 90, 180 and 270 degrees in that order.
Result<std::vector<AssetView>> RenderAssetViews(const AssetRecord& record, const AssetMesh& mesh, const AssetViewOptions& options);

// The four views as one picture, two by two (-y and +x above, +y and -x below), `gap` px apart, each
// captioned with the side it shows.
Result<Image> AssetViewSheet(const std::vector<AssetView>& views, int gap = 6);

}  // namespace villa

#pragma once
// Wavefront OBJ and MTL, the parts a furniture model needs: vertex positions, polygon faces (triangulated:
// a fan for convex faces, ear clipping in the face's plane otherwise), `usemtl` switching materials,
// `mtllib`, and from MTL the diffuse colour (Kd), opacity (d, or Tr = 1 - d) and diffuse texture (map_Kd).
// Texture coordinates, normals, smoothing groups, lines and points are read past. Coordinates stay in the
// file's frame and unit; converting to the asset frame is the importer's job.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/mesh.h"
#include "util/result.h"

namespace villa {

struct ObjModel {
  struct Group {
    std::string material;                         // the `usemtl` name, "" before any
    std::vector<std::array<int, 3>> triangles;    // indices into positions
  };
  std::vector<Vec3> positions;
  std::vector<Group> groups;                      // one per material, in order of first use
  std::vector<std::string> material_libraries;    // `mtllib` file names, relative to the OBJ's folder
  int faces = 0;                                  // polygons read (before triangulation)
  int degenerate_faces = 0;                       // `f` lines with one or two corners, left out

  int TriangleCount() const;
};

struct ObjMaterial {
  std::string name;
  std::array<double, 3> diffuse{0.8, 0.8, 0.8};  // Kd, [0, 1]
  double alpha = 1.0;                            // d (opacity), [0, 1]
  std::string diffuse_texture;                   // map_Kd file name, relative to the MTL's folder ("" = none)
};

// Errors name `where` and the line: "<where>:120: face index 913 out of range (900 vertices)".
Result<ObjModel> ParseObj(std::string_view text, const std::string& where);
Result<std::vector<ObjMaterial>> ParseMtl(std::string_view text, const std::string& where);

}  // namespace villa

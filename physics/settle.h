#pragma once
// Dropping a furnished scene into a physics engine (issue 28): Bullet (double precision, Debian
// libbullet-dev) as the paper's PyBullet. The building is static with its exact triangles (those facing
// down left out: nothing rests on an underside, and a wall's bottom in the floor's plane gave contacts
// that walked heavy boxes sideways); every free
// object is a rigid body whose collision shape is the convex hulls of its mesh's connected pieces (our
// procedural assets are built from convex pieces, so for them the shape is exact; an imported model's
// non-convex piece becomes its hull); welded objects (wall- and ceiling-hung, garments on a rail) hold
// still and collide. After `seconds` of simulated time each free object's largest displacement (over its
// box corners) and turn tell whether it stood still: strict 1 cm / 0.1 rad, loose 20 cm / 8 degrees
// (SceneSmith's rule and a looser one). Bullet stays inside settle.cpp; this header speaks plain types.
#include <string>
#include <vector>

#include "mesh/mesh.h"
#include "util/result.h"

namespace villa::physics {

// m: a body that starts deeper than this inside another (or the building) is a defect (issue 28).
inline constexpr double kStartsInside = 0.002;

struct SettleBody {
  std::string id;
  TriangleMesh mesh;    // world frame (plan: metres, z up); each connected piece one convex part
  bool welded = false;  // held where it is (hung on a wall or from the ceiling, on a rail)
};

struct SettleOptions {
  double seconds = 2.0;          // simulated time, (0, 60]
  double step = 1.0 / 240.0;     // fixed time step, s, (0, 0.05]
  double density = 600.0;        // kg/m3 of the hulls' volume (wood, upholstery), (0, 20000]
  double friction = 0.6;         // (0, 2]
  double margin = 0.0005;        // m, Bullet's collision margin round each hull, [0, 0.01]
  double strict_move = 0.01, strict_turn = 0.1;                // m, rad
  double loose_move = 0.2, loose_turn = 8.0 * 3.14159265358979323846 / 180.0;
  std::string Check() const;  // empty when usable
};

struct BodyMotion {
  double moved = 0.0;   // m: the largest displacement of its box's corners
  double turned = 0.0;  // rad: the angle of its rotation
  Vec3 shift;           // m: how its box's centre moved
  // Before the first step: how deep (m, >= 0) it starts inside another body or the building (Bullet's
  // contact distance between convex parts, margins included), and what that is ("" when nothing;
  // "building" for the static triangles).
  double start_depth = 0.0;
  std::string start_against;
  Vec3 start_out;  // unit: the way out of what it starts inside (the contact's normal), world frame
  bool welded = false;
  bool strict = true;   // within strict_move and strict_turn (welded ones always)
  bool loose = true;
  int parts = 0;        // convex parts of its shape
};

struct SettleResult {
  std::vector<BodyMotion> bodies;  // parallel to the input
  int free = 0, strict = 0, loose = 0;  // free bodies, and those stable by each rule
  int starts_inside = 0;           // bodies that start more than 2 mm inside another or the building
  int parts = 0;                   // convex parts in all
  int static_triangles = 0;
  int steps = 0;                   // steps simulated: fewer than seconds / step when every free body fell asleep
  double seconds = 0.0;            // wall-clock
};

// The convex parts of a mesh: the vertices of each piece joined through shared vertex indices, open pieces
// joined where they meet (pieces of fewer than 4 vertices or no volume are dropped); a piece that is a
// stack of prisms (a tray with a rim; an imported one within 3 degrees and 2 mm) in its convex prisms
// (mesh/convex_parts.h), not its hull. With `guides`, a piece that does not fill its hull to 90 % (an
// imported bed in one piece, whose headboard, rails and footboard span a wedge over the mattress) is cut by
// up to 5 levels of planes across its axes, each at its vertices' or the guide boxes' levels (what starts
// inside it), where a cut most shrinks the sum of its sides' hulls (by at least 2 litres). Settle cuts only
// the bodies that another body starts inside, guided by those bodies' boxes.
std::vector<std::vector<Vec3>> ConnectedPieces(const TriangleMesh& mesh, const std::vector<Box3>* guides = nullptr);

Result<SettleResult> Settle(const std::vector<TriangleMesh>& statics, const std::vector<SettleBody>& bodies,
                            const SettleOptions& options = {});

}  // namespace villa::physics

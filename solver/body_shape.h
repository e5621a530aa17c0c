#pragma once
// Which box of a body a cost term sees, in the body's own asset frame, unscaled (the scale parameter
// multiplies every length): the body itself (no offset, half its size, 0..its height) or one of its
// interaction zones (a box beside it).
namespace villa::solver {

struct BodyShape {
  double cx = 0.0;  // box centre offset along asset x and y (m)
  double cy = 0.0;
  double hx = 0.5;  // half extents along asset x and y (m)
  double hy = 0.5;
  double z0 = 0.0;  // box bottom and top above the body's bottom (m)
  double z1 = 1.0;
};

}  // namespace villa::solver

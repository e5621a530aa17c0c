// Every residual's autodiff Jacobian against central differences, at configurations where the term is
// active (non-zero) and away from its kinks; and each term is zero where its condition holds.
#include <catch2/catch.hpp>

#include <memory>
#include <vector>

#include "solver/residuals.h"

namespace villa::solver {
namespace {

using Blocks = std::vector<std::vector<double>>;

// Evaluates the cost function's residuals at `blocks`.
std::vector<double> Residuals(const ceres::CostFunction& cost, Blocks& blocks) {
  std::vector<double*> ptrs;
  for (auto& b : blocks) ptrs.push_back(b.data());
  std::vector<double> r(cost.num_residuals());
  REQUIRE(cost.Evaluate(ptrs.data(), r.data(), nullptr));
  return r;
}

double Norm2(const std::vector<double>& r) {
  double s = 0.0;
  for (double v : r) s += v * v;
  return s;
}

// Autodiff Jacobians against central differences, entry by entry.
void CheckJacobians(ceres::CostFunction* raw, Blocks blocks) {
  std::unique_ptr<ceres::CostFunction> cost(raw);
  const int m = cost->num_residuals();
  std::vector<double*> ptrs;
  for (auto& b : blocks) ptrs.push_back(b.data());
  std::vector<std::vector<double>> jac(blocks.size());
  std::vector<double*> jptrs;
  for (size_t b = 0; b < blocks.size(); ++b) {
    jac[b].assign(m * blocks[b].size(), 0.0);
    jptrs.push_back(jac[b].data());
  }
  std::vector<double> r(m);
  REQUIRE(cost->Evaluate(ptrs.data(), r.data(), jptrs.data()));
  REQUIRE(Norm2(r) > 1e-8);  // the configuration makes the term active: the check means something
  double largest = 0.0;
  for (size_t b = 0; b < blocks.size(); ++b) {
    const int n = static_cast<int>(blocks[b].size());
    for (int k = 0; k < n; ++k) {
      const double h = 1e-6, keep = blocks[b][k];
      blocks[b][k] = keep + h;
      const std::vector<double> plus = Residuals(*cost, blocks);
      blocks[b][k] = keep - h;
      const std::vector<double> minus = Residuals(*cost, blocks);
      blocks[b][k] = keep;
      for (int i = 0; i < m; ++i) {
        const double numeric = (plus[i] - minus[i]) / (2 * h);
        const double analytic = jac[b][i * n + k];
        INFO("block " << b << " parameter " << k << " residual " << i);
        CHECK(analytic == Approx(numeric).margin(1e-5).epsilon(1e-5));
        largest = std::max(largest, std::abs(analytic));
      }
    }
  }
  CHECK(largest > 1e-3);  // some parameter moves the residual
}

const BodyShape kSofa{0.0, 0.0, 1.0, 0.45, 0.0, 0.85};
const BodyShape kTable{0.0, 0.0, 0.5, 0.3, 0.0, 0.45};

TEST_CASE("Penetration residual gradient matches differences and vanishes when apart", "[solver]") {
  CheckJacobians(PenetrationResidual::Create(kSofa, kTable, false, 0.02, 10.0), {{1.0, 1.0, 0.0, 0.3}, {1.0}, {1.6, 1.3, 0.0, 0.1}, {1.05}});
  // A hung body: z is a separating axis.
  CheckJacobians(PenetrationResidual::Create(kSofa, kTable, true, 0.02, 10.0), {{1.0, 1.0, 0.0, 0.3}, {1.0}, {1.2, 1.1, 0.7, 0.2}, {1.0}});
  std::unique_ptr<ceres::CostFunction> cost(PenetrationResidual::Create(kSofa, kTable, false, 0.02, 10.0));
  Blocks apart = {{0.0, 0.0, 0.0, 0.0}, {1.0}, {3.0, 0.0, 0.0, 0.0}, {1.0}};
  CHECK(Norm2(Residuals(*cost, apart)) == 0.0);
  Blocks above = {{0.0, 0.0, 0.0, 0.0}, {1.0}, {0.0, 0.0, 1.0, 0.0}, {1.0}};  // a painting above a sofa
  CHECK(Norm2(Residuals(*cost, above)) == 0.0);
}

TEST_CASE("Interaction zone residual gradient matches differences", "[solver]") {
  const BodyShape zone{0.0, -(0.45 + 0.225), 1.0, 0.225, 0.0, 0.85};
  CheckJacobians(InteractionZoneResidual::Create(zone, kTable, 2.0), {{1.0, 2.0, 0.0, 0.2}, {1.0}, {1.2, 1.35, 0.0, -0.3}, {1.0}});
}

TEST_CASE("Keep-out residual gradient matches differences and respects heights", "[solver]") {
  const Ring door = {{0.0, 0.0}, {0.9, 0.0}, {0.9, 0.9}, {0.0, 0.9}};
  CheckJacobians(KeepOutResidual::Create(kTable, door, 0.0, 2.1, false, 0.02, 10.0), {{0.8, 1.0, 0.0, 0.4}, {1.0}});
  CheckJacobians(KeepOutResidual::Create(kTable, door, 0.9, 2.1, true, 0.02, 10.0), {{0.5, 0.5, 0.6, 0.1}, {1.0}});
  std::unique_ptr<ceres::CostFunction> window(KeepOutResidual::Create(kTable, door, 0.9, 2.1, false, 0.02, 10.0));
  Blocks low = {{0.4, 0.4, 0.0, 0.0}, {1.0}};  // 0.45 high under a sill at 0.9
  CHECK(Norm2(Residuals(*window, low)) == 0.0);
}

TEST_CASE("Footprint-in-polygon residual gradient matches differences on a non-convex floor", "[solver]") {
  const Ring l = {{0, 0}, {6, 0}, {6, 2.5}, {3, 2.5}, {3, 5}, {0, 5}};
  CheckJacobians(FootprintInPolygonResidual::Create(kSofa, l, 0.01, 10.0), {{5.6, 1.0, 0.0, 0.3}, {1.0}});
  CheckJacobians(FootprintInPolygonResidual::Create(kSofa, l, 0.01, 10.0), {{2.6, 3.3, 0.0, 1.2}, {1.1}});
  std::unique_ptr<ceres::CostFunction> cost(FootprintInPolygonResidual::Create(kSofa, l, 0.01, 10.0));
  Blocks inside = {{1.5, 1.0, 0.0, 0.0}, {1.0}};
  CHECK(Norm2(Residuals(*cost, inside)) == 0.0);
}

TEST_CASE("Reflex-vertex residual gradient matches differences", "[solver]") {
  CheckJacobians(ReflexVertexResidual::Create(kSofa, {{3.0, 2.5}}, 0.01, 10.0), {{3.2, 2.3, 0.0, 0.25}, {1.0}});
  std::unique_ptr<ceres::CostFunction> cost(ReflexVertexResidual::Create(kSofa, {{3.0, 2.5}}, 0.01, 10.0));
  Blocks clear = {{1.0, 1.0, 0.0, 0.0}, {1.0}};
  CHECK(Norm2(Residuals(*cost, clear)) == 0.0);
}

TEST_CASE("Wall-span residual gradient matches differences and holds on the wall piece", "[solver]") {
  CheckJacobians(WallSpanResidual::Create(kSofa, {0.0, 0.0}, {1.0, 0.0}, 3.0, 0.01, 10.0), {{0.7, 0.47, 0.0, 0.05}, {1.0}});
  CheckJacobians(WallSpanResidual::Create(kSofa, {4.0, 1.0}, {0.0, 1.0}, 2.0, 0.01, 10.0), {{3.5, 2.5, 0.0, 1.6}, {1.1}});
  std::unique_ptr<ceres::CostFunction> cost(WallSpanResidual::Create(kSofa, {0.0, 0.0}, {1.0, 0.0}, 3.0, 0.01, 10.0));
  Blocks middle = {{1.5, 0.47, 0.0, 0.0}, {1.0}};
  CHECK(Norm2(Residuals(*cost, middle)) == 0.0);
}

TEST_CASE("Containment residual gradient matches differences", "[solver]") {
  const BodyShape book{0.0, 0.0, 0.03, 0.11, 0.0, 0.24};
  CheckJacobians(ContainmentResidual::Create(book, -0.43, -0.16, 0.43, 0.14, 0.35, 0.005, 10.0), {{0.42, 0.05, 0.12, 0.2}, {1.2}});
  std::unique_ptr<ceres::CostFunction> cost(ContainmentResidual::Create(book, -0.43, -0.16, 0.43, 0.14, 0.4, 0.005, 10.0));
  Blocks fits = {{0.0, 0.0, 0.02, 0.0}, {1.0}};
  CHECK(Norm2(Residuals(*cost, fits)) == 0.0);
}

TEST_CASE("Semantic residual gradients match differences", "[solver]") {
  CheckJacobians(FaceToResidual::Create(kSofa, kTable, 0.5236, 1.9), {{0.0, 0.0, 0.0, 1.3}, {1.0}, {1.0, -3.0, 0.0, 0.0}, {1.0}});
  // Behind the sofa's centre line and past its end: both parts of the side residual are active.
  CheckJacobians(RelativeSideResidual::Create(kTable, kSofa, RelativeSideResidual::kFront, 1.0),
                 {{1.6, 0.4, 0.0, 0.1}, {1.0}, {0.0, 0.0, 0.0, 0.2}, {1.0}});
  CheckJacobians(RelativeSideResidual::Create(kTable, kSofa, RelativeSideResidual::kLeft, 1.0),
                 {{-0.5, 1.0, 0.0, 0.1}, {1.0}, {0.0, 0.0, 0.0, 0.2}, {1.0}});
  CheckJacobians(GapResidual::Create(kTable, kSofa, 0.5, 1.5, 1.0), {{0.3, -2.8, 0.0, 0.1}, {1.0}, {0.0, 0.0, 0.0, 0.2}, {1.0}});
  CheckJacobians(GapResidual::Create(kTable, kSofa, 0.0, 0.5, 1.0), {{0.3, -1.6, 0.0, 0.1}, {1.0}, {0.0, 0.0, 0.0, 0.2}, {1.0}});
  CheckJacobians(AlignResidual::Create(0.0873, 1.9), {{0.0, 0.0, 0.0, 0.4}, {1.0, 1.0, 0.0, 1.5}});
  CheckJacobians(CenteredResidual::Create(kTable, kSofa, 0.05, 1.0), {{0.4, -0.9, 0.0, 0.0}, {1.0}, {0.0, 0.0, 0.0, 0.2}, {1.0}});
  CheckJacobians(ScalePriorResidual::Create(0.5), {{1.2}});
  CheckJacobians(YawPriorResidual::Create(1.5708, 0.2), {{0.0, 0.0, 0.0, 1.7}});
}

TEST_CASE("Semantic residuals vanish where the relation holds", "[solver]") {
  auto zero = [](ceres::CostFunction* raw, Blocks blocks) {
    std::unique_ptr<ceres::CostFunction> cost(raw);
    return Norm2(Residuals(*cost, blocks)) == 0.0;
  };
  // A table 0.3 m in front of a sofa at yaw 0 (front = -y), centred, facing it back.
  Blocks front = {{0.0, -1.05, 0.0, 0.0}, {1.0}, {0.0, 0.0, 0.0, 0.0}, {1.0}};
  CHECK(zero(RelativeSideResidual::Create(kTable, kSofa, RelativeSideResidual::kFront, 1.0), front));
  CHECK(zero(GapResidual::Create(kTable, kSofa, 0.0, 0.5, 1.0), front));
  CHECK(zero(CenteredResidual::Create(kTable, kSofa, 0.05, 1.0), front));
  CHECK(zero(FaceToResidual::Create(kSofa, kTable, 0.5236, 1.0), {{0.0, 0.0, 0.0, 0.0}, {1.0}, {0.1, -2.0, 0.0, 0.0}, {1.0}}));
  CHECK(zero(AlignResidual::Create(0.0873, 1.0), {{0.0, 0.0, 0.0, 0.02}, {0.0, 0.0, 0.0, 1.5708}}));
  CHECK_FALSE(zero(RelativeSideResidual::Create(kTable, kSofa, RelativeSideResidual::kBehind, 1.0), front));
  // Sides are bands: in front of the centre line and within the width. A painting hung on the wall behind
  // the sofa (its centre 0.4 m behind the sofa's, in front of the sofa's back face) is behind it; a table
  // in front but past the sofa's end is not in front of it.
  CHECK(zero(RelativeSideResidual::Create(kTable, kSofa, RelativeSideResidual::kBehind, 1.0),
             {{0.2, 0.4, 1.2, 0.0}, {1.0}, {0.0, 0.0, 0.0, 0.0}, {1.0}}));
  CHECK_FALSE(zero(RelativeSideResidual::Create(kTable, kSofa, RelativeSideResidual::kFront, 1.0),
                   {{1.6, -1.0, 0.0, 0.0}, {1.0}, {0.0, 0.0, 0.0, 0.0}, {1.0}}));
}

}  // namespace
}  // namespace villa::solver

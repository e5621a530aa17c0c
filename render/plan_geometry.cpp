#include "render/plan_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "layout/geometry.h"

namespace villa::plan {
namespace {

Point Sub(Point a, Point b) { return {a.x - b.x, a.y - b.y}; }
double Cross(Point a, Point b) { return a.x * b.y - a.y * b.x; }

// Segments p1-p2 and q1-q2 cross at a single point strictly inside both.
bool ProperlyCross(Point p1, Point p2, Point q1, Point q2) {
  const double d1 = Cross(Sub(p2, p1), Sub(q1, p1));
  const double d2 = Cross(Sub(p2, p1), Sub(q2, p1));
  const double d3 = Cross(Sub(q2, q1), Sub(p1, q1));
  const double d4 = Cross(Sub(q2, q1), Sub(p2, q1));
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

bool Inside(Point p, const Ring& ring) { return PointInRing(p, ring, 0); }

}  // namespace

double SignedDistanceToRing(Point p, const Ring& ring) {
  if (ring.empty()) return -std::numeric_limits<double>::infinity();
  const double best = DistanceToBoundary(p, ring);
  return Inside(p, ring) ? best : -best;
}

Point PoleOfInaccessibility(const Ring& ring, double precision) {
  Point average;
  for (const Point& p : ring) {
    average.x += p.x;
    average.y += p.y;
  }
  if (!ring.empty()) {
    average.x /= static_cast<double>(ring.size());
    average.y /= static_cast<double>(ring.size());
  }
  if (ring.size() < 3 || Area(ring) <= 0.0) return average;

  double min_x = ring[0].x, max_x = ring[0].x, min_y = ring[0].y, max_y = ring[0].y;
  for (const Point& p : ring) {
    min_x = std::min(min_x, p.x);
    max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y);
    max_y = std::max(max_y, p.y);
  }
  const double cell_size = std::min(max_x - min_x, max_y - min_y);
  if (cell_size <= 0.0) return average;
  precision = std::max(precision, cell_size * 1e-6);

  struct Cell {
    Point centre;
    double half = 0.0;
    double distance = 0.0;   // signed distance of the centre to the boundary
    double potential = 0.0;  // the best distance any point of the cell can have
  };
  auto make_cell = [&](Point c, double half) {
    Cell cell{c, half, SignedDistanceToRing(c, ring), 0.0};
    cell.potential = cell.distance + half * std::sqrt(2.0);
    return cell;
  };
  auto lower = [](const Cell& a, const Cell& b) { return a.potential < b.potential; };
  std::priority_queue<Cell, std::vector<Cell>, decltype(lower)> queue(lower);
  const double half = cell_size / 2.0;
  for (double x = min_x; x < max_x; x += cell_size) {
    for (double y = min_y; y < max_y; y += cell_size) queue.push(make_cell({x + half, y + half}, half));
  }

  // Start from the area centroid (often right for convex rooms) and the box centre.
  Point centroid;
  double twice_area = 0.0;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const double f = ring[j].x * ring[i].y - ring[i].x * ring[j].y;
    centroid.x += (ring[j].x + ring[i].x) * f;
    centroid.y += (ring[j].y + ring[i].y) * f;
    twice_area += f;
  }
  Cell best = make_cell(average, 0.0);
  if (twice_area != 0.0) {
    const Cell c = make_cell({centroid.x / (3.0 * twice_area), centroid.y / (3.0 * twice_area)}, 0.0);
    if (c.distance > best.distance) best = c;
  }
  const Cell box = make_cell({(min_x + max_x) / 2.0, (min_y + max_y) / 2.0}, 0.0);
  if (box.distance > best.distance) best = box;

  for (int steps = 0; !queue.empty() && steps < 200000; ++steps) {
    const Cell cell = queue.top();
    queue.pop();
    if (cell.distance > best.distance) best = cell;
    if (cell.potential - best.distance <= precision) continue;
    const double h = cell.half / 2.0;
    queue.push(make_cell({cell.centre.x - h, cell.centre.y - h}, h));
    queue.push(make_cell({cell.centre.x + h, cell.centre.y - h}, h));
    queue.push(make_cell({cell.centre.x - h, cell.centre.y + h}, h));
    queue.push(make_cell({cell.centre.x + h, cell.centre.y + h}, h));
  }
  return best.centre;
}

std::vector<Polyline> ChainSegments(const std::vector<Segment>& segments, double tolerance) {
  // Nodes: segment ends merged within the tolerance.
  std::vector<Point> nodes;
  auto node_of = [&](Point p) {
    for (size_t i = 0; i < nodes.size(); ++i) {
      if (Distance(nodes[i], p) <= tolerance) return static_cast<int>(i);
    }
    nodes.push_back(p);
    return static_cast<int>(nodes.size() - 1);
  };
  struct Edge {
    int from;
    int to;
  };
  std::vector<Edge> edges;
  for (const Segment& s : segments) {
    if (Length(s) <= tolerance) continue;
    edges.push_back({node_of(s.a), node_of(s.b)});
  }
  std::vector<std::vector<int>> incident(nodes.size());
  for (size_t e = 0; e < edges.size(); ++e) {
    incident[edges[e].from].push_back(static_cast<int>(e));
    incident[edges[e].to].push_back(static_cast<int>(e));
  }
  std::vector<bool> used(edges.size(), false);
  std::vector<Polyline> chains;

  auto walk = [&](int start_node, int first_edge) {
    Polyline line;
    line.points.push_back(nodes[start_node]);
    int node = start_node;
    int edge = first_edge;
    while (edge >= 0 && !used[edge]) {
      used[edge] = true;
      node = edges[edge].from == node ? edges[edge].to : edges[edge].from;
      if (node == start_node) {
        line.closed = true;
        break;
      }
      line.points.push_back(nodes[node]);
      edge = -1;
      if (incident[node].size() == 2) {
        for (int next : incident[node]) {
          if (!used[next]) edge = next;
        }
      }
    }
    chains.push_back(std::move(line));
  };

  // Open chains start at ends and junctions; what is left afterwards are closed loops.
  for (size_t n = 0; n < nodes.size(); ++n) {
    if (incident[n].size() == 2) continue;
    for (int e : incident[n]) {
      if (!used[e]) walk(static_cast<int>(n), e);
    }
  }
  for (size_t e = 0; e < edges.size(); ++e) {
    if (!used[e]) walk(edges[e].from, static_cast<int>(e));
  }
  return chains;
}

std::vector<Segment> ClipSegmentToRing(Point a, Point b, const Ring& ring) {
  std::vector<double> cuts = {0.0, 1.0};
  const Point d = Sub(b, a);
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Point e = Sub(ring[i], ring[j]);
    const double denominator = Cross(d, e);
    if (std::abs(denominator) < 1e-15) continue;
    const Point w = Sub(ring[j], a);
    const double t = Cross(w, e) / denominator;
    const double u = Cross(w, d) / denominator;
    if (t > 0.0 && t < 1.0 && u >= 0.0 && u <= 1.0) cuts.push_back(t);
  }
  std::sort(cuts.begin(), cuts.end());
  std::vector<Segment> inside;
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (cuts[i + 1] - cuts[i] < 1e-9) continue;
    const double mid = (cuts[i] + cuts[i + 1]) / 2.0;
    if (!Inside({a.x + d.x * mid, a.y + d.y * mid}, ring)) continue;
    const Segment piece{{a.x + d.x * cuts[i], a.y + d.y * cuts[i]}, {a.x + d.x * cuts[i + 1], a.y + d.y * cuts[i + 1]}};
    if (!inside.empty() && Distance(inside.back().b, piece.a) < 1e-9) {
      inside.back().b = piece.b;
    } else {
      inside.push_back(piece);
    }
  }
  return inside;
}

bool RectInsideRing(Point min, Point max, const Ring& ring) {
  const Point corners[4] = {min, {max.x, min.y}, max, {min.x, max.y}};
  for (const Point& c : corners) {
    if (!Inside(c, ring)) return false;
  }
  for (const Point& p : ring) {
    if (p.x > min.x && p.x < max.x && p.y > min.y && p.y < max.y) return false;
  }
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    for (int k = 0; k < 4; ++k) {
      if (ProperlyCross(ring[j], ring[i], corners[k], corners[(k + 1) % 4])) return false;
    }
  }
  return true;
}

bool RectOverlapsRing(Point min, Point max, const Ring& ring) {
  if (ring.size() < 3) return false;
  const Point corners[4] = {min, {max.x, min.y}, max, {min.x, max.y}};
  for (const Point& c : corners) {
    if (Inside(c, ring)) return true;
  }
  for (const Point& p : ring) {
    if (p.x > min.x && p.x < max.x && p.y > min.y && p.y < max.y) return true;
  }
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    for (int k = 0; k < 4; ++k) {
      if (ProperlyCross(ring[j], ring[i], corners[k], corners[(k + 1) % 4])) return true;
    }
  }
  return false;
}

}  // namespace villa::plan

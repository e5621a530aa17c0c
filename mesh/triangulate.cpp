// Ear clipping of a polygon with holes, in the manner of mapbox's earcut (but keeping every vertex): a doubly linked ring, holes
// bridged into the outer ring, ears cut with a point-in-triangle test over reflex vertices, and two
// fallback passes (cure local self-intersections, split along a valid diagonal) for awkward rings.
// Conventions here: outer ring counter-clockwise, holes clockwise, Cross() > 0 for a left turn.
#include "mesh/triangulate.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace villa {
namespace {

struct Node {
  int i = 0;
  double x = 0.0;
  double y = 0.0;
  Node* prev = nullptr;
  Node* next = nullptr;
};

double Cross(const Node* a, const Node* b, const Node* c) {
  return (b->x - a->x) * (c->y - a->y) - (b->y - a->y) * (c->x - a->x);
}
bool Equals(const Node* a, const Node* b) { return a->x == b->x && a->y == b->y; }
int Sign(double v) { return (v > 0.0) - (v < 0.0); }

bool OnSegment(const Node* p, const Node* q, const Node* r) {
  return q->x <= std::max(p->x, r->x) && q->x >= std::min(p->x, r->x) && q->y <= std::max(p->y, r->y) &&
         q->y >= std::min(p->y, r->y);
}

bool Intersects(const Node* p1, const Node* q1, const Node* p2, const Node* q2) {
  int o1 = Sign(Cross(p1, q1, p2));
  int o2 = Sign(Cross(p1, q1, q2));
  int o3 = Sign(Cross(p2, q2, p1));
  int o4 = Sign(Cross(p2, q2, q1));
  if (o1 != o2 && o3 != o4) return true;
  if (o1 == 0 && OnSegment(p1, p2, q1)) return true;
  if (o2 == 0 && OnSegment(p1, q2, q1)) return true;
  if (o3 == 0 && OnSegment(p2, p1, q2)) return true;
  if (o4 == 0 && OnSegment(p2, q1, q2)) return true;
  return false;
}

bool PointInTriangle(const Node* a, const Node* b, const Node* c, const Node* p) {
  return Cross(a, b, p) >= 0.0 && Cross(b, c, p) >= 0.0 && Cross(c, a, p) >= 0.0;
}

class EarClipper {
 public:
  std::vector<std::array<int, 3>> triangles;

  Node* MakeRing(const Ring& ring, int first_index, bool counter_clockwise) {
    Node* last = nullptr;
    bool keep = (SignedArea(ring) > 0.0) == counter_clockwise;
    int n = static_cast<int>(ring.size());
    for (int k = 0; k < n; ++k) {
      int j = keep ? k : n - 1 - k;
      last = Insert(first_index + j, ring[j].x, ring[j].y, last);
    }
    if (last && Equals(last, last->next)) {
      Node* next = last->next;
      Remove(last);
      last = next;
    }
    return last;
  }

  // Removes repeated points between start and end, and collinear ones too when `drop_collinear` (the
  // rescue passes: a first pass keeps collinear vertices as corners of proper triangles, so no
  // zero-area triangle is made where one can be avoided).
  Node* Filter(Node* start, Node* end = nullptr, bool drop_collinear = true) {
    if (!start) return start;
    if (!end) end = start;
    Node* p = start;
    bool again;
    do {
      again = false;
      bool repeated = Equals(p, p->next);
      if (repeated || (drop_collinear && std::abs(Cross(p->prev, p, p->next)) <= Epsilon(p->prev, p, p->next))) {
        // A collinear vertex leaves as a zero-area triangle: its two edges stay in the triangulation, so
        // a face meeting this one along them shares every vertex (a watertight solid, no T-junctions).
        if (!repeated && !Equals(p->prev, p) && !Equals(p->prev, p->next))
          triangles.push_back({p->prev->i, p->i, p->next->i});
        Remove(p);
        p = end = p->prev;
        if (p == p->next) break;
        again = true;
      } else {
        p = p->next;
      }
    } while (again || p != end);
    return end;
  }

  void Clip(Node* ear, int pass) {
    if (!ear) return;
    Node* stop = ear;
    while (ear->prev != ear->next) {
      Node* prev = ear->prev;
      Node* next = ear->next;
      if (IsEar(ear)) {
        triangles.push_back({prev->i, ear->i, next->i});
        Remove(ear);
        ear = next->next;
        stop = next->next;
        continue;
      }
      ear = next;
      if (ear == stop) {
        if (pass == 0) {
          Clip(Filter(ear), 1);
        } else if (pass == 1) {
          Clip(CureLocalIntersections(Filter(ear)), 2);
        } else {
          SplitClip(ear);
        }
        break;
      }
    }
  }

  Node* BridgeHoles(Node* outer, std::vector<Node*> holes) {
    // Leftmost hole first, each bridged to the nearest outer vertex it can see.
    std::vector<Node*> leftmost;
    for (Node* h : holes) {
      Node* best = h;
      Node* p = h;
      do {
        if (p->x < best->x || (p->x == best->x && p->y < best->y)) best = p;
        p = p->next;
      } while (p != h);
      leftmost.push_back(best);
    }
    std::sort(leftmost.begin(), leftmost.end(), [](Node* a, Node* b) { return a->x < b->x; });
    for (size_t k = 0; k < leftmost.size(); ++k) {
      Node* hole = leftmost[k];
      Node* bridge = FindBridge(hole, outer, leftmost, k);
      if (!bridge) continue;  // a hole outside the outer ring or unreachable: left out
      Node* reverse = Split(bridge, hole);
      Filter(reverse, reverse->next, false);
      outer = Filter(bridge, bridge->next, false);
    }
    return outer;
  }

 private:
  std::deque<Node> nodes_;

  static double Epsilon(const Node* a, const Node* b, const Node* c) {
    double scale = std::max({std::abs(a->x), std::abs(a->y), std::abs(b->x), std::abs(b->y), std::abs(c->x),
                             std::abs(c->y), 1.0});
    return 1e-14 * scale * scale;
  }

  Node* Insert(int i, double x, double y, Node* last) {
    nodes_.push_back(Node{i, x, y});
    Node* p = &nodes_.back();
    if (!last) {
      p->prev = p;
      p->next = p;
    } else {
      p->next = last->next;
      p->prev = last;
      last->next->prev = p;
      last->next = p;
    }
    return p;
  }

  static void Remove(Node* p) {
    p->next->prev = p->prev;
    p->prev->next = p->next;
  }

  bool IsEar(Node* ear) const {
    const Node* a = ear->prev;
    const Node* b = ear;
    const Node* c = ear->next;
    if (Cross(a, b, c) <= 0.0) return false;  // reflex or flat
    for (const Node* p = c->next; p != a; p = p->next) {
      if (Equals(p, a) || Equals(p, b) || Equals(p, c)) continue;
      if (PointInTriangle(a, b, c, p) && Cross(p->prev, p, p->next) <= 0.0) return false;
    }
    return true;
  }

  static bool LocallyInside(const Node* a, const Node* b) {
    if (Cross(a->prev, a, a->next) > 0.0) return Cross(a, b, a->next) <= 0.0 && Cross(a, a->prev, b) <= 0.0;
    return Cross(a, b, a->prev) > 0.0 || Cross(a, a->next, b) > 0.0;
  }

  static bool MiddleInside(const Node* a, const Node* b) {
    const Node* p = a;
    bool inside = false;
    double px = (a->x + b->x) / 2.0;
    double py = (a->y + b->y) / 2.0;
    do {
      if (((p->y > py) != (p->next->y > py)) && p->next->y != p->y &&
          (px < (p->next->x - p->x) * (py - p->y) / (p->next->y - p->y) + p->x))
        inside = !inside;
      p = p->next;
    } while (p != a);
    return inside;
  }

  static bool IntersectsRing(const Node* a, const Node* b) {
    const Node* p = a;
    do {
      if (p->i != a->i && p->next->i != a->i && p->i != b->i && p->next->i != b->i && Intersects(p, p->next, a, b))
        return true;
      p = p->next;
    } while (p != a);
    return false;
  }

  static bool IsValidDiagonal(const Node* a, const Node* b) {
    return a->next->i != b->i && a->prev->i != b->i && !IntersectsRing(a, b) &&
           ((LocallyInside(a, b) && LocallyInside(b, a) && MiddleInside(a, b) &&
             (Cross(a->prev, a, b->prev) != 0.0 || Cross(a, b->prev, b) != 0.0)) ||
            (Equals(a, b) && Cross(a->prev, a, a->next) > 0.0 && Cross(b->prev, b, b->next) > 0.0));
  }

  // Links a and b by a diagonal: two rings where there was one; returns the copy of b.
  Node* Split(Node* a, Node* b) {
    nodes_.push_back(Node{a->i, a->x, a->y});
    Node* a2 = &nodes_.back();
    nodes_.push_back(Node{b->i, b->x, b->y});
    Node* b2 = &nodes_.back();
    Node* an = a->next;
    Node* bp = b->prev;
    a->next = b;
    b->prev = a;
    a2->next = an;
    an->prev = a2;
    b2->next = a2;
    a2->prev = b2;
    bp->next = b2;
    b2->prev = bp;
    return b2;
  }

  Node* CureLocalIntersections(Node* start) {
    if (!start) return start;
    Node* p = start;
    do {
      Node* a = p->prev;
      Node* b = p->next->next;
      if (!Equals(a, b) && Intersects(a, p, p->next, b) && LocallyInside(a, b) && LocallyInside(b, a)) {
        triangles.push_back({a->i, p->i, b->i});
        Remove(p);
        Remove(p->next);
        p = start = b;
      }
      p = p->next;
    } while (p != start);
    return Filter(p);
  }

  void SplitClip(Node* start) {
    Node* a = start;
    do {
      for (Node* b = a->next->next; b != a->prev; b = b->next) {
        if (a->i != b->i && IsValidDiagonal(a, b)) {
          Node* c = Split(a, b);
          a = Filter(a, a->next);
          c = Filter(c, c->next);
          Clip(a, 0);
          Clip(c, 0);
          return;
        }
      }
      a = a->next;
    } while (a != start);
  }

  static bool SegmentHitsRing(const Node* s, const Node* t, const Node* ring) {
    const Node* p = ring;
    do {
      const Node* q = p->next;
      bool touches = Equals(p, s) || Equals(q, s) || Equals(p, t) || Equals(q, t);
      if (!touches && Intersects(p, q, s, t)) return true;
      p = q;
    } while (p != ring);
    return false;
  }

  // The outer vertex nearest to `hole` whose connecting segment crosses no edge of the outer ring or of
  // a hole not yet bridged, and enters the outer ring's interior at that vertex.
  Node* FindBridge(Node* hole, Node* outer, const std::vector<Node*>& holes, size_t current) const {
    std::vector<std::pair<double, Node*>> candidates;
    Node* p = outer;
    do {
      double dx = p->x - hole->x;
      double dy = p->y - hole->y;
      candidates.push_back({dx * dx + dy * dy, p});
      p = p->next;
    } while (p != outer);
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [distance, m] : candidates) {
      if (!LocallyInside(m, hole)) continue;
      if (SegmentHitsRing(m, hole, outer)) continue;
      bool blocked = false;
      for (size_t k = current; k < holes.size() && !blocked; ++k) blocked = SegmentHitsRing(m, hole, holes[k]);
      if (!blocked) return m;
    }
    return nullptr;
  }
};

}  // namespace

std::vector<std::array<int, 3>> TriangulatePolygon(const Ring& outer, const std::vector<Ring>& holes) {
  EarClipper clipper;
  if (outer.size() < 3) return {};
  double extent = 0.0;
  for (Point p : outer) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
  if (std::abs(SignedArea(outer)) <= 1e-12 * std::max(1.0, extent * extent)) return {};
  Node* ring = clipper.MakeRing(outer, 0, true);
  int offset = static_cast<int>(outer.size());
  std::vector<Node*> hole_rings;
  for (const Ring& hole : holes) {
    if (hole.size() >= 3) {
      Node* h = clipper.MakeRing(hole, offset, false);
      if (h && h != h->next) hole_rings.push_back(h);
    }
    offset += static_cast<int>(hole.size());
  }
  if (!hole_rings.empty()) ring = clipper.BridgeHoles(ring, hole_rings);
  ring = clipper.Filter(ring, nullptr, false);
  if (ring && ring->next != ring->prev) clipper.Clip(ring, 0);
  return std::move(clipper.triangles);
}

}  // namespace villa

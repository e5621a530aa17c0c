#pragma once
// Layouts the building tests share, as JSON text (FORMAT.md).
#include <string_view>

namespace villa::testing {

// Three floors, valid by FORMAT.md: an angled footprint edge on the ground floor (mitred corners),
// T-, X- and L-junctions of interior walls, a terrace over the part of the ground floor that the
// first floor leaves uncovered, the 4 x 4 utility room at (0, 0) on every floor.
inline constexpr std::string_view kThreeFloorVilla = R"json({
  "rooms": {
    "utility-room_0/0": {"shape": "shapely.box(0, 0, 4, 4)"},
    "kitchen_0/0": {"shape": "shapely.box(4, 0, 9, 4)"},
    "dining-room_0/0": {"shape": "shapely.box(9, 0, 14, 4)"},
    "living-room_0/0": {"shape": "shapely.Polygon([(0, 4), (14, 4), (14, 6), (12, 10), (6, 10), (6, 7), (0, 7)])"},
    "bathroom_0/0": {"shape": "shapely.box(0, 7, 3, 10)"},
    "bedroom_0/0": {"shape": "shapely.box(3, 7, 6, 10)"},
    "utility-room_1/0": {"shape": "shapely.box(0, 0, 4, 4)"},
    "bedroom_1/0": {"shape": "shapely.box(4, 0, 9, 4)"},
    "office_1/0": {"shape": "shapely.box(0, 4, 4, 7)"},
    "bathroom_1/0": {"shape": "shapely.box(4, 4, 9, 7)"},
    "utility-room_2/0": {"shape": "shapely.box(0, 0, 4, 4)"},
    "children-room_2/0": {"shape": "shapely.Polygon([(4, 0), (9, 0), (9, 7), (0, 7), (0, 4), (4, 4)])"}
  },
  "entrance": {
    "main_door": {"shape": "shapely.LineString([(7, 10), (9, 10)])", "level": 0}
  },
  "doors": {
    "living0_kitchen0": {"shape": "shapely.LineString([(5, 4), (7, 4)])", "level": 0},
    "living0_bathroom0": {"shape": "shapely.LineString([(1, 7), (2, 7)])", "level": 0},
    "living0_bedroom0": {"shape": "shapely.LineString([(6, 8), (6, 9)])", "level": 0},
    "utility1_bedroom1": {"shape": "shapely.LineString([(4, 1.5), (4, 2.5)])", "level": 1},
    "office1_bathroom1": {"shape": "shapely.LineString([(4, 5), (4, 6)])", "level": 1}
  },
  "opens": {
    "utility0_living0": {"shape": "shapely.LineString([(1, 4), (3, 4)])", "level": 0},
    "kitchen0_dining0": {"shape": "shapely.LineString([(9, 1), (9, 3)])", "level": 0},
    "utility1_office1": {"shape": "shapely.LineString([(1, 4), (3, 4)])", "level": 1},
    "utility2_children2": {"shape": "shapely.LineString([(1, 4), (3, 4)])", "level": 2}
  },
  "windows": {
    "kitchen0_window": {"shape": "shapely.LineString([(5, 0), (7, 0)])", "is_panoramic": 0, "level": 0},
    "dining0_window": {"shape": "shapely.LineString([(14, 1), (14, 3)])", "is_panoramic": 0, "level": 0},
    "living0_pano": {"shape": "shapely.LineString([(13.5, 7), (12.5, 9)])", "is_panoramic": 1, "level": 0},
    "bathroom0_window": {"shape": "shapely.LineString([(0, 8), (0, 9)])", "is_panoramic": 0, "level": 0},
    "bedroom0_window": {"shape": "shapely.LineString([(4, 10), (5, 10)])", "is_panoramic": 0, "level": 0},
    "bedroom1_window": {"shape": "shapely.LineString([(6, 0), (8, 0)])", "is_panoramic": 0, "level": 1},
    "bathroom1_window": {"shape": "shapely.LineString([(9, 5), (9, 6)])", "is_panoramic": 0, "level": 1},
    "office1_window": {"shape": "shapely.LineString([(0, 5), (0, 6)])", "is_panoramic": 0, "level": 1},
    "children2_window": {"shape": "shapely.LineString([(6, 0), (8, 0)])", "is_panoramic": 0, "level": 2},
    "children2_pano": {"shape": "shapely.LineString([(9, 2), (9, 5)])", "is_panoramic": 1, "level": 2}
  },
  "interiors": {
    "wall_utility0_kitchen0": {"shape": "shapely.LineString([(4, 0), (4, 4)])", "level": 0},
    "wall_kitchen0_dining0": {"shape": "shapely.LineString([(9, 0), (9, 4)])", "level": 0},
    "wall_utility0_living0": {"shape": "shapely.LineString([(0, 4), (4, 4)])", "level": 0},
    "wall_kitchen0_living0": {"shape": "shapely.LineString([(4, 4), (9, 4)])", "level": 0},
    "wall_dining0_living0": {"shape": "shapely.LineString([(9, 4), (14, 4)])", "level": 0},
    "wall_living0_bathroom0": {"shape": "shapely.LineString([(0, 7), (3, 7)])", "level": 0},
    "wall_living0_bedroom0_a": {"shape": "shapely.LineString([(3, 7), (6, 7)])", "level": 0},
    "wall_living0_bedroom0_b": {"shape": "shapely.LineString([(6, 7), (6, 10)])", "level": 0},
    "wall_bathroom0_bedroom0": {"shape": "shapely.LineString([(3, 7), (3, 10)])", "level": 0},
    "wall_utility1_bedroom1": {"shape": "shapely.LineString([(4, 0), (4, 4)])", "level": 1},
    "wall_utility1_office1": {"shape": "shapely.LineString([(0, 4), (4, 4)])", "level": 1},
    "wall_bedroom1_bathroom1": {"shape": "shapely.LineString([(4, 4), (9, 4)])", "level": 1},
    "wall_office1_bathroom1": {"shape": "shapely.LineString([(4, 4), (4, 7)])", "level": 1},
    "wall_utility2_children2_a": {"shape": "shapely.LineString([(4, 0), (4, 4)])", "level": 2},
    "wall_utility2_children2_b": {"shape": "shapely.LineString([(0, 4), (4, 4)])", "level": 2}
  }
})json";

// Two floors on a U-shaped footprint (from `villa synth --seed 5`, record 16): an interior wall ends on
// the facade right beside the courtyard notch, so the wall must be trimmed at the exterior wall's inner
// face, not run out into the notch.
inline constexpr std::string_view kUShapedHouse = R"json({"rooms": {"utility-room_0/0": {"shape": "shapely.box(3, 0, 7, 4)"}, "living-room_0/0": {"shape": "shapely.Polygon([(0, 0), (3, 0), (3, 4), (7, 4), (7, 0), (10.5, 0), (10.5, 10.5), (9, 10.5), (9, 6), (4.5, 6), (4.5, 10.5), (0, 10.5)])"}, "kitchen_0/0": {"shape": "shapely.box(9, 10.5, 13, 13)"}, "bathroom_0/0": {"shape": "shapely.box(0, 10.5, 4.5, 13)"}, "dining-room_0/0": {"shape": "shapely.box(10.5, 0, 13, 10.5)"}, "utility-room_1/0": {"shape": "shapely.box(3, 0, 7, 4)"}, "living-room_1/0": {"shape": "shapely.Polygon([(0, 2.5), (3, 2.5), (3, 4), (7, 4), (7, 2.5), (10.5, 2.5), (10.5, 9), (9, 9), (9, 6), (4.5, 6), (4.5, 8), (0, 8)])"}, "bedroom_1/0": {"shape": "shapely.box(7, 0, 10.5, 2.5)"}, "bathroom_1/0": {"shape": "shapely.box(0, 0, 3, 2.5)"}, "meeting-room_1/0": {"shape": "shapely.box(10.5, 0, 13, 5.5)"}, "balcony_1/0": {"shape": "shapely.box(10.5, 5.5, 13, 9)"}}, "entrance": {"main_door": {"shape": "shapely.LineString([(0, 9), (0, 8)])", "level": 0}}, "doors": {"living0_dining0": {"shape": "shapely.LineString([(10.5, 2.5), (10.5, 3.5)])", "level": 0}, "living0_utility0": {"shape": "shapely.LineString([(7, 1.5), (7, 0.5)])", "level": 0}, "living0_bathroom0": {"shape": "shapely.LineString([(2.5, 10.5), (1.5, 10.5)])", "level": 0}, "utility1_bathroom1": {"shape": "shapely.LineString([(3, 2), (3, 1)])", "level": 1}, "utility1_bedroom1": {"shape": "shapely.LineString([(7, 0.5), (7, 1.5)])", "level": 1}, "living1_balcony1": {"shape": "shapely.LineString([(10.5, 7), (10.5, 8)])", "level": 1}, "living1_meeting1": {"shape": "shapely.LineString([(10.5, 4), (10.5, 5)])", "level": 1}}, "opens": {"kitchen0_dining0": {"shape": "shapely.LineString([(11, 10.5), (12.5, 10.5)])", "level": 0}, "utility1_living1": {"shape": "shapely.LineString([(5.5, 4), (3.5, 4)])", "level": 1}}, "windows": {"bathroom0_window": {"shape": "shapely.LineString([(1.5, 13), (0.5, 13)])", "is_panoramic": 0, "level": 0}, "kitchen0_window": {"shape": "shapely.LineString([(11, 13), (9.5, 13)])", "is_panoramic": 0, "level": 0}, "living0_window": {"shape": "shapely.LineString([(9, 10), (9, 8)])", "is_panoramic": 0, "level": 0}, "living0_window_2": {"shape": "shapely.LineString([(4.5, 6.5), (4.5, 8.5)])", "is_panoramic": 0, "level": 0}, "dining0_window": {"shape": "shapely.LineString([(13, 7), (13, 8.5)])", "is_panoramic": 0, "level": 0}, "bathroom1_window": {"shape": "shapely.LineString([(0, 2), (0, 1)])", "is_panoramic": 0, "level": 1}, "bedroom1_window": {"shape": "shapely.LineString([(7.5, 0), (8.5, 0)])", "is_panoramic": 0, "level": 1}, "living1_window": {"shape": "shapely.LineString([(0, 7.5), (0, 5)])", "is_panoramic": 0, "level": 1}, "living1_window_2": {"shape": "shapely.LineString([(3, 8), (1, 8)])", "is_panoramic": 0, "level": 1}, "meeting1_window": {"shape": "shapely.LineString([(13, 4), (13, 5)])", "is_panoramic": 0, "level": 1}, "balcony1_pano": {"shape": "shapely.LineString([(13, 7), (13, 8.5)])", "is_panoramic": 1, "level": 1}, "utility1_window": {"shape": "shapely.LineString([(5.5, 0), (6.5, 0)])", "is_panoramic": 0, "level": 1}}, "interiors": {"wall_utility0_living0": {"shape": "shapely.LineString([(3, 4), (3, 0)])", "level": 0}, "wall_utility0_living0_2": {"shape": "shapely.LineString([(7, 4), (3, 4)])", "level": 0}, "wall_utility0_living0_3": {"shape": "shapely.LineString([(7, 0), (7, 4)])", "level": 0}, "wall_living0_kitchen0": {"shape": "shapely.LineString([(10.5, 10.5), (9, 10.5)])", "level": 0}, "wall_living0_bathroom0": {"shape": "shapely.LineString([(4.5, 10.5), (0, 10.5)])", "level": 0}, "wall_living0_dining0": {"shape": "shapely.LineString([(10.5, 0), (10.5, 10.5)])", "level": 0}, "wall_kitchen0_dining0": {"shape": "shapely.LineString([(10.5, 10.5), (13, 10.5)])", "level": 0}, "wall_utility1_living1": {"shape": "shapely.LineString([(3, 4), (3, 2.5)])", "level": 1}, "wall_utility1_living1_2": {"shape": "shapely.LineString([(7, 4), (3, 4)])", "level": 1}, "wall_utility1_living1_3": {"shape": "shapely.LineString([(7, 2.5), (7, 4)])", "level": 1}, "wall_utility1_bedroom1": {"shape": "shapely.LineString([(7, 0), (7, 2.5)])", "level": 1}, "wall_utility1_bathroom1": {"shape": "shapely.LineString([(3, 2.5), (3, 0)])", "level": 1}, "wall_living1_bedroom1": {"shape": "shapely.LineString([(7, 2.5), (10.5, 2.5)])", "level": 1}, "wall_living1_bathroom1": {"shape": "shapely.LineString([(0, 2.5), (3, 2.5)])", "level": 1}, "wall_living1_meeting1": {"shape": "shapely.LineString([(10.5, 2.5), (10.5, 5.5)])", "level": 1}, "wall_living1_balcony1": {"shape": "shapely.LineString([(10.5, 5.5), (10.5, 9)])", "level": 1}, "wall_bedroom1_meeting1": {"shape": "shapely.LineString([(10.5, 0), (10.5, 2.5)])", "level": 1}, "wall_meeting1_balcony1": {"shape": "shapely.LineString([(13, 5.5), (10.5, 5.5)])", "level": 1}}})json";

}  // namespace villa::testing

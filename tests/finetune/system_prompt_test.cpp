// The system prompt: the resource file compiled in byte for byte, its example a valid canonical layout,
// and every rule of FORMAT.md stated.
#include <catch2/catch.hpp>

#include "finetune/layout_schema.h"
#include "finetune/system_prompt.h"
#include "finetune_test_util.h"
#include "layout/layout_io.h"
#include "layout/validate.h"

using namespace villa;
using namespace villa::testing;

TEST_CASE("SystemPrompt is the resource file without its trailing newline", "[finetune][prompt]") {
  std::string file = Slurp(fs::path(VILLA_SOURCE_DIR) / "finetune" / "system_prompt.md");
  REQUIRE(!file.empty());
  REQUIRE(file.back() == '\n');
  while (!file.empty() && file.back() == '\n') file.pop_back();
  CHECK(SystemPrompt() == file);
  CHECK(SystemPrompt().back() != '\n');
}

TEST_CASE("The example answer in the prompt is a valid layout in canonical compact form", "[finetune][prompt]") {
  const std::string_view prompt = SystemPrompt();
  const auto start = prompt.rfind("\n{\"rooms\"");
  REQUIRE(start != std::string_view::npos);
  const std::string example(prompt.substr(start + 1));
  auto layout = ParseLayoutText(example, "system_prompt.md example");
  REQUIRE(layout.ok());
  CHECK(ValidateLayout(*layout).valid());
  CHECK(LayoutToString(*layout, -1) == example);  // exactly what an exported answer looks like
  CHECK(MatchLayoutJsonSchema(Json::parse(example)).ok());
}

TEST_CASE("The prompt states the output shape and every rule of FORMAT.md", "[finetune][prompt]") {
  const std::string prompt(SystemPrompt());
  for (const char* key : {"\"rooms\"", "\"entrance\"", "\"doors\"", "\"opens\"", "\"windows\"", "\"interiors\""}) {
    INFO(key);
    CHECK(prompt.find(key) != std::string::npos);
  }
  for (const char* category : {"living-room", "bedroom", "kitchen", "bathroom", "dining-room", "children-room", "office",
                               "meeting-room", "utility-room", "balcony"}) {
    INFO(category);
    CHECK(prompt.find(category) != std::string::npos);
  }
  // Shapes, units, names, levels, and the figures of rules 1-10.
  for (const char* fact : {"shapely.box(min_x, min_y, max_x, max_y)", "shapely.Polygon([(x1, y1), (x2, y2), ...])",
                           "shapely.LineString([(x1, y1), (x2, y2)])", "counter-clockwise", "two decimals", "metres",
                           "category_L/i", "kitchen_1/1", "\"level\"", "\"is_panoramic\": 1", "2.8 m", "no gap", "no hole",
                           "no larger", "exactly two rooms", "exactly one room", "outer boundary", "0.8 m", "0.6 m",
                           "1.0 m", "At most 3 floors", "6 rooms", "4 x 4 m", "same coordinates", "exact centre",
                           "reached from the entrance", "Every kitchen and every bathroom has a window",
                           "entered through a door", "dining room", "only be reached through another room"}) {
    INFO(fact);
    CHECK(prompt.find(fact) != std::string::npos);
  }
}

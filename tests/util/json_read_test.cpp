// Reading outside JSON: a nesting limit, duplicate keys named with both places, member order kept, and
// objects with many members read in linear time.
#include <catch2/catch.hpp>

#include <string>

#include "util/excerpt.h"
#include "util/text_table.h"
#include "util/json_read.h"

using namespace villa;
using OJson = nlohmann::ordered_json;

TEST_CASE("values nested deeper than the limit are refused with their place", "[util][json]") {
  // 100,000 open brackets (the issue's 200 KB file) and a room value nested 200,000 deep.
  const std::string brackets(100000, '[');
  auto deep = ParseJson<OJson>(brackets, "deep.json");
  REQUIRE_FALSE(deep.ok());
  CHECK(deep.error() == "deep.json: line 1, column 65: nested deeper than 64 levels");
  const std::string room = "{\n\"rooms\": {\"kitchen_0/0\": " + std::string(200000, '[') + std::string(200000, ']') + "}}";
  auto nested = ParseJson<nlohmann::json>(room, "layout.json");
  REQUIRE_FALSE(nested.ok());
  CHECK(nested.error() == "layout.json: line 2, column 88: nested deeper than 64 levels");
  // At the limit it reads.
  const std::string at_limit = std::string(64, '[') + std::string(64, ']');
  CHECK(ParseJson<OJson>(at_limit, "ok.json").ok());
  CHECK_FALSE(ParseJson<OJson>("[" + at_limit + "]", "ok.json").ok());
}

TEST_CASE("a duplicate key is an error naming the key, its object and both places", "[util][json]") {
  const std::string text =
      "{\n"
      "  \"rooms\": {\n"
      "    \"kitchen_0/0\": {\"shape\": \"shapely.box(0, 0, 4, 4)\"},\n"
      "    \"bedroom_0/0\": {\"shape\": \"shapely.box(4, 0, 8, 4)\"},\n"
      "    \"kitchen_0/0\": {\"shape\": \"shapely.box(8, 0, 9, 4)\"}\n"
      "  }\n"
      "}\n";
  auto parsed = ParseJson<OJson>(text, "layout.json");
  REQUIRE_FALSE(parsed.ok());
  CHECK(parsed.error() == "layout.json: rooms: duplicate key \"kitchen_0/0\" on lines 3 and 5");
  // One line (a JSONL record): columns; an escaped spelling is the same key; the top level has no path.
  auto line = ParseJson<OJson>(R"({"a": 1, "b": [{"x": 1, "\u0078": 2}]})", "data.jsonl:4");
  REQUIRE_FALSE(line.ok());
  CHECK(line.error() == "data.jsonl:4: b[0]: duplicate key \"x\" at columns 17 and 25");
  auto top = ParseJson<OJson>("{\"rooms\": {},\n \"rooms\": {}}", "");
  REQUIRE_FALSE(top.ok());
  CHECK(top.error() == "duplicate key \"rooms\" on lines 1 and 2");
  // The same key in different objects is fine.
  CHECK(ParseJson<OJson>(R"({"a": {"x": 1}, "b": {"x": 2}})", "ok").ok());
}

TEST_CASE("syntax errors keep the parser's words, values and member order come through", "[util][json]") {
  auto bad = ParseJson<OJson>("{\"a\": tru}", "x.json");
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.error().rfind("x.json: not valid JSON: [json.exception.parse_error.101] parse error at line 1, column 10", 0) == 0);
  auto good = ParseJson<OJson>(R"({"z": 1, "a": [true, null, 2.5, "s", {"k": -3}], "m": 18446744073709551615})", "");
  REQUIRE(good.ok());
  CHECK(good->dump() == R"({"z":1,"a":[true,null,2.5,"s",{"k":-3}],"m":18446744073709551615})");
  auto plain = ParseJson<nlohmann::json>(R"({"z": 1, "a": 2})", "");
  REQUIRE(plain.ok());
  CHECK(plain->dump() == R"({"a":2,"z":1})");
  CHECK_FALSE(ParseJson<OJson>("{} {}", "").ok());  // one value only
}

TEST_CASE("an object with 100,000 members reads whole and in order", "[util][json]") {
  // (nlohmann's own ordered parse looks each key up in a list: minutes here; bench/ times the difference)
  std::string text = "{";
  for (int i = 0; i < 100000; ++i) text += (i ? ",\"d" : "\"d") + std::to_string(i) + "\":" + std::to_string(i);
  text += "}";
  auto parsed = ParseJson<OJson>(text, "");
  REQUIRE(parsed.ok());
  REQUIRE(parsed->size() == 100000);
  int expected = 0;
  bool in_order = true;
  for (auto it = parsed->begin(); it != parsed->end(); ++it, ++expected)
    in_order = in_order && it.key() == "d" + std::to_string(expected) && *it == expected;
  CHECK(in_order);
}

TEST_CASE("excerpts keep short values whole and cut long ones at 80 bytes", "[util][excerpt]") {
  CHECK(Excerpt("kitchen_0/0") == "kitchen_0/0");
  const std::string long_name(10000000, 'n');
  CHECK(Excerpt(long_name) == std::string(77, 'n') + "...");
  CHECK(Excerpt(std::string(80, 'x')) == std::string(80, 'x'));
  // A cut never splits a UTF-8 character: "é" is two bytes.
  std::string accents;
  for (int i = 0; i < 60; ++i) accents += "\xC3\xA9";
  const std::string cut = Excerpt(accents);
  CHECK(cut.size() <= 80);
  CHECK(cut.substr(cut.size() - 3) == "...");
  CHECK((cut.size() - 3) % 2 == 0);
}

TEST_CASE("text printed on a terminal cannot drive it: control bytes and bad UTF-8 are escaped", "[util][excerpt][issue33]") {
  CHECK(villa::Printable("Caf\xc3\xa9 chair") == "Caf\xc3\xa9 chair");
  CHECK(villa::Printable("a\x1b]0;pwned\x07z") == "a\\x1b]0;pwned\\x07z");
  CHECK(villa::Printable("\xc2\x9b" "2J") == "\\xc2\\x9b2J");  // the C1 CSI
  CHECK(villa::Printable("x\xff") == "x\\xff");
  villa::TextTable table({"id", "name"});
  table.AddRow({"lib:1", "evil\x1b[2Jname"});
  CHECK(table.Render().find("evil\\x1b[2Jname") != std::string::npos);
}

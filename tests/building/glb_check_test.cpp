// Untrusted .glb files are checked before the importer sees them (issue 33): each defect found in the
// adversarial pass gives an error naming the file and the bad value, none a crash or a silent score.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "building/export.h"

using namespace villa;

namespace {

// A GLB of this JSON and no binary chunk.
std::string Glb(const nlohmann::json& j) {
  std::string text = j.dump();
  while (text.size() % 4) text += ' ';
  auto u32 = [](uint32_t v) {
    std::string s(4, '\0');
    for (int k = 0; k < 4; ++k) s[k] = static_cast<char>((v >> (8 * k)) & 0xff);
    return s;
  };
  return "glTF" + u32(2) + u32(static_cast<uint32_t>(20 + text.size())) + u32(static_cast<uint32_t>(text.size())) + u32(0x4E4F534Au) + text;
}

nlohmann::json Chain(int depth) {
  nlohmann::json nodes = nlohmann::json::array();
  for (int i = 0; i < depth; ++i) nodes.push_back(i + 1 < depth ? nlohmann::json{{"children", {i + 1}}} : nlohmann::json::object());
  return {{"asset", {{"version", "2.0"}}}, {"scenes", {{{"nodes", {0}}}}}, {"nodes", nodes}};
}

}  // namespace

TEST_CASE("a .glb is checked before the importer: header, hierarchy, outside files, coordinates", "[building][glb][issue33]") {
  CHECK(CheckGlbStructure(Glb(Chain(5)), "ok.glb").ok());
  CHECK(CheckGlbStructure("v 0 0 0\nv 1 0 0\nf 1 2 3\n", "x.glb").error() == "x.glb: not a binary glTF (.glb): no \"glTF\" header");
  std::string torn = Glb(Chain(3));
  torn.resize(torn.size() - 4);
  CHECK(CheckGlbStructure(torn, "t.glb").error().find("t.glb: the header says ") == 0);
  // 15,000 nested nodes crashed the recursive walk: refused by depth, without recursion.
  CHECK(CheckGlbStructure(Glb(Chain(15000)), "deep.glb").error() ==
        "deep.glb: nodes nested 257 deep, more than the 256 a scene may be");
  nlohmann::json two = Chain(3);
  two["nodes"][0]["children"] = {1, 2};
  two["nodes"][1]["children"] = {2};
  CHECK(CheckGlbStructure(Glb(two), "two.glb").error() == "two.glb: node 2 has two parents (0 and 1)");
  nlohmann::json cycle = Chain(3);
  cycle["nodes"][2]["children"] = {0};
  CHECK(CheckGlbStructure(Glb(cycle), "c.glb").error().find("is its own ancestor (a cycle)") != std::string::npos);
  nlohmann::json outside = Chain(1);
  outside["buffers"] = {{{"uri", "/etc/passwd"}, {"byteLength", 10}}};
  CHECK(CheckGlbStructure(Glb(outside), "o.glb").error() ==
        "o.glb: a buffer refers to an outside file (\"/etc/passwd\"); only embedded buffers are read");
  nlohmann::json far = Chain(2);
  far["nodes"][1]["translation"] = {1e38, 0, 0};
  CHECK(CheckGlbStructure(Glb(far), "far.glb").error().find("far.glb: node 1: \"translation\" [1e+38,0,0] is not finite numbers within") == 0);
  nlohmann::json nan = Chain(1);
  nan["nodes"][0]["mesh"] = 0;
  nan["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}};
  nan["accessors"] = {{{"count", 3}, {"type", "VEC3"}, {"componentType", 5126}, {"min", {0, 0, 0}}, {"max", {1, nullptr, 1}}}};
  CHECK(CheckGlbStructure(Glb(nan), "nan.glb").error().find("nan.glb: accessor 0 (POSITION): min/max missing, not finite") == 0);
  nlohmann::json wrong = Chain(1);
  wrong["meshes"] = {1};
  CHECK(CheckGlbStructure(Glb(wrong), "w.glb").error().find("w.glb: malformed glTF JSON: ") == 0);
}

#include <catch2/catch.hpp>

#include "assets/java_properties.h"
#include "assets/obj_model.h"
#include "assets/zip_archive.h"
#include "sh3f_fixture.h"

namespace villa {
namespace {

TEST_CASE("Zip entries read back stored and deflated, found by name with or without case", "[assets][zip]") {
  for (bool deflate : {false, true}) {
    INFO("deflate " << deflate);
    std::string big(100000, 'x');
    auto zip = ZipArchive::FromBytes(test::ZipBytes({{"a/b.txt", "hello"}, {"Big.OBJ", big}, {"empty", ""}}, deflate), "t.zip");
    REQUIRE(zip.ok());
    REQUIRE(zip->entries().size() == 3);
    CHECK(*zip->Read("a/b.txt") == "hello");
    CHECK(*zip->Read("/a/b.txt") == "hello");  // SH3D catalogs name models with a leading '/'
    CHECK(*zip->Read("empty") == "");
    REQUIRE(zip->FindIgnoringCase("big.obj"));
    CHECK(*zip->Read(*zip->FindIgnoringCase("big.obj")) == big);
    CHECK(zip->Find("big.obj") == nullptr);
    CHECK(zip->Read("c.txt").error() == "t.zip: c.txt: no such entry");
  }
}

TEST_CASE("Damaged zip archives give errors naming the archive and the entry", "[assets][zip]") {
  std::string bytes = test::ZipBytes({{"model.obj", std::string(5000, 'v')}}, true);
  CHECK(ZipArchive::FromBytes("PK", "tiny.zip").error() == "tiny.zip: not a readable zip archive: only 2 bytes");
  CHECK(ZipArchive::FromBytes(std::string(100, 'x'), "junk.zip").error() ==
        "junk.zip: not a readable zip archive: no end-of-central-directory record");
  // Flip a byte of the deflated data: inflate fails or the CRC does not match; either names the entry.
  std::string corrupt = bytes;
  corrupt[30 + 9 + 3] ^= 0x5A;
  auto zip = ZipArchive::FromBytes(corrupt, "c.zip");
  REQUIRE(zip.ok());
  auto read = zip->Read("model.obj");
  REQUIRE_FALSE(read.ok());
  CHECK(read.error().rfind("c.zip: model.obj: ", 0) == 0);
  CHECK((read.error().find("corrupt deflate data") != std::string::npos || read.error().find("CRC-32 mismatch") != std::string::npos ||
         read.error().find("longer or shorter") != std::string::npos));
  // A method we do not read (bzip2 = 12) in the local and central headers.
  std::string odd = test::ZipBytes({{"m.obj", "v 0 0 0\n"}}, false);
  odd[8] = 12;
  std::size_t central = odd.find(std::string("PK\x01\x02", 4));
  odd[central + 10] = 12;
  auto zip2 = ZipArchive::FromBytes(odd, "o.zip");
  REQUIRE(zip2.ok());
  CHECK(zip2->Read("m.obj").error() == "o.zip: m.obj: compression method 12 is not supported (only stored and deflated)");
}

TEST_CASE("Java properties: comments, continuations, separators, escapes and Latin-1", "[assets][properties]") {
  std::string text =
      "# comment = not a key\n"
      "   ! also a comment\n"
      "plain=value\n"
      "spaced   :   value with spaces  \n"
      "bare value after a blank\n"
      "long=first \\\n"
      "      second \\\n"
      "\tthird\n"
      "escaped\\=key=a\\tb\\nc\n"
      "unicode=Bill 10\\u20ac \\uD83D\\uDE00\n"
      "latin1=Ren\xE9\r\n"
      "empty=\n"
      "twice=1\n"
      "twice=2\n"
      "backslash=C:\\\\path\\\\\n"
      "after=ok";
  auto p = ParseJavaProperties(text, "cat.properties");
  REQUIRE(p.ok());
  CHECK(p->at("plain") == "value");
  CHECK(p->at("spaced") == "value with spaces  ");
  CHECK(p->at("bare") == "value after a blank");
  CHECK(p->at("long") == "first second third");
  CHECK(p->at("escaped=key") == "a\tb\nc");
  CHECK(p->at("unicode") == "Bill 10\xE2\x82\xAC \xF0\x9F\x98\x80");
  CHECK(p->at("latin1") == "Ren\xC3\xA9");
  CHECK(p->at("empty") == "");
  CHECK(p->at("twice") == "2");
  CHECK(p->at("backslash") == "C:\\path\\");
  CHECK(p->at("after") == "ok");
  CHECK(p->count("# comment") == 0);
  CHECK(p->size() == 11);

  auto bad = ParseJavaProperties("a=1\nname#3=Caf\\u00g9\n", "lib.sh3f: catalog");
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.error() == "lib.sh3f: catalog:2: malformed \\uXXXX escape: \\u00g9");
}

TEST_CASE("OBJ faces are triangulated in their plane, concave ones without covering their notch", "[assets][obj]") {
  // An L-shaped hexagon (concave) in the x-z plane, and a quad given with negative indices.
  std::string obj =
      "mtllib m.mtl\n"
      "v 0 0 0\nv 2 0 0\nv 2 0 1\nv 1 0 1\nv 1 0 2\nv 0 0 2\n"
      "usemtl wood\n"
      "f 1/1/1 6//2 5 4 3 2  # counter-clockwise seen from +y: faces +y\n"
      "v 0 1 0\nv 1 1 0\nv 1 1 1\nv 0 1 1\n"
      "usemtl cloth\n"
      "f -4 -1 -2 -3\n"
      "f 1 2\n";
  auto model = ParseObj(obj, "l.obj");
  REQUIRE(model.ok());
  CHECK(model->material_libraries == std::vector<std::string>{"m.mtl"});
  REQUIRE(model->groups.size() == 2);
  CHECK(model->groups[0].material == "wood");
  CHECK(model->faces == 2);
  CHECK(model->degenerate_faces == 1);
  REQUIRE(model->groups[0].triangles.size() == 4);
  double area = 0;
  for (const auto& t : model->groups[0].triangles) {
    Vec3 a = model->positions[t[0]], b = model->positions[t[1]], c = model->positions[t[2]];
    Vec3 n = Cross(b - a, c - a);
    CHECK(n.y > 0);  // the face's own winding is kept
    area += Norm(n) / 2;
  }
  CHECK(area == Approx(3.0));  // the L's area: a fan from corner 1 would cover 4
  CHECK(model->groups[1].triangles.size() == 2);
  CHECK(model->TriangleCount() == 6);

  CHECK(ParseObj("v 0 0 0\nv 1 0 0\nf 1 2 3\n", "a.obj").error() == "a.obj:3: face index 3 out of range (2 vertices)");
  CHECK(ParseObj("v 0 0\n", "b.obj").error() == "b.obj:1: vertex needs 3 coordinates: v 0 0");
  CHECK(ParseObj("v 0 nan 0\n", "c.obj").error() == "c.obj:1: vertex coordinates must be finite numbers: v 0 nan 0");
  CHECK(ParseObj("v 0 0 0\nf 1 x 1\n", "d.obj").error() == "d.obj:2: bad face corner 'x'");
}

TEST_CASE("MTL: diffuse colour, opacity both ways, texture after options", "[assets][obj]") {
  auto m = ParseMtl("newmtl glass\nKd 0.5 0.6 0.7\nd 0.25\nnewmtl wood\nKd 0.3\nTr 0.1\nmap_Kd -s 1 1 1 -clamp on wood.jpg\n", "m.mtl");
  REQUIRE(m.ok());
  REQUIRE(m->size() == 2);
  CHECK((*m)[0].name == "glass");
  CHECK((*m)[0].diffuse[2] == Approx(0.7));
  CHECK((*m)[0].alpha == Approx(0.25));
  CHECK((*m)[1].diffuse[1] == Approx(0.3));  // "Kd r" is grey
  CHECK((*m)[1].alpha == Approx(0.9));
  CHECK((*m)[1].diffuse_texture == "wood.jpg");
  CHECK(ParseMtl("Kd 1 1 1\n", "x.mtl").error() == "x.mtl:1: Kd before any newmtl");
}

}  // namespace
}  // namespace villa

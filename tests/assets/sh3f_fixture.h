#pragma once
// A small Sweet Home 3D furniture library made in the test: a zip archive (stored or deflated entries)
// holding a catalog and OBJ/MTL models (y up, front +z, cm, origin off-centre as SH3D models often are).
#include <zlib.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <stb_image_write.h>

#include "assets/zip_archive.h"
#include "mesh/mesh.h"
#include "util/atomic_file.h"

namespace villa::test {

using ZipEntries = std::vector<std::pair<std::string, std::string>>;

inline void Put16(std::string* out, std::uint32_t v) {
  out->push_back(static_cast<char>(v & 0xFF));
  out->push_back(static_cast<char>((v >> 8) & 0xFF));
}
inline void Put32(std::string* out, std::uint32_t v) {
  Put16(out, v & 0xFFFF);
  Put16(out, v >> 16);
}

inline std::string RawDeflate(const std::string& data) {
  z_stream z{};
  deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, -MAX_WBITS, 8, Z_DEFAULT_STRATEGY);
  std::string out(deflateBound(&z, data.size()), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = static_cast<uInt>(data.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

// A zip archive of `entries`, each deflated or stored.
inline std::string ZipBytes(const ZipEntries& entries, bool deflate) {
  std::string out, directory;
  for (const auto& [name, data] : entries) {
    std::string packed = deflate ? RawDeflate(data) : data;
    std::uint32_t offset = static_cast<std::uint32_t>(out.size());
    std::uint32_t crc = ZipCrc32(data);
    auto header = [&](std::string* to, bool central) {
      Put32(to, central ? 0x02014b50 : 0x04034b50);
      if (central) Put16(to, 20);  // made by
      Put16(to, 20);               // needed
      Put16(to, 0);                // flags
      Put16(to, deflate ? 8 : 0);
      Put16(to, 0);  // time
      Put16(to, 0);  // date
      Put32(to, crc);
      Put32(to, static_cast<std::uint32_t>(packed.size()));
      Put32(to, static_cast<std::uint32_t>(data.size()));
      Put16(to, static_cast<std::uint32_t>(name.size()));
      Put16(to, 0);  // extra
      if (central) {
        Put16(to, 0);  // comment
        Put16(to, 0);  // disk
        Put16(to, 0);  // internal attributes
        Put32(to, 0);  // external attributes
        Put32(to, offset);
      }
      *to += name;
    };
    header(&out, false);
    out += packed;
    header(&directory, true);
  }
  std::uint32_t directory_offset = static_cast<std::uint32_t>(out.size());
  out += directory;
  Put32(&out, 0x06054b50);
  Put16(&out, 0);
  Put16(&out, 0);
  Put16(&out, static_cast<std::uint32_t>(entries.size()));
  Put16(&out, static_cast<std::uint32_t>(entries.size()));
  Put32(&out, static_cast<std::uint32_t>(directory.size()));
  Put32(&out, directory_offset);
  Put16(&out, 0);
  return out;
}

// OBJ text made of boxes (each a closed cuboid of six quads, its own eight corners), in model units.
class ObjWriter {
 public:
  void Material(const std::string& name) { text_ += "usemtl " + name + "\n"; }
  void Box(Vec3 lo, Vec3 hi) {
    for (int i = 0; i < 8; ++i) {
      Vec3 p{i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z};
      text_ += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    }
    // Corner k = x + 2y + 4z; quads counter-clockwise seen from outside; relative indices (-8 = first).
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads)
      text_ += "f " + std::to_string(q[0] - 8) + " " + std::to_string(q[1] - 8) + " " + std::to_string(q[2] - 8) + " " +
               std::to_string(q[3] - 8) + "\n";
  }
  // A flat grid of n x n quads in the x-z plane at height y (a rug), many triangles.
  void Grid(double size, double y, int n) {
    int first = vertices_ + 1;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        text_ += "v " + std::to_string(size * i / n) + " " + std::to_string(y) + " " + std::to_string(size * j / n) + "\n";
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        int a = first + j * (n + 1) + i;
        text_ += "f " + std::to_string(a) + " " + std::to_string(a + n + 1) + " " + std::to_string(a + n + 2) + " " +
                 std::to_string(a + 1) + "\n";
      }
    vertices_ += (n + 1) * (n + 1);
  }
  std::string Text(const std::string& mtllib) const { return (mtllib.empty() ? "" : "mtllib " + mtllib + "\n") + text_; }

 private:
  std::string text_;
  int vertices_ = 0;  // absolute-index vertices written by Grid (boxes use relative indices)
};

// A bookcase 80 x 30 x 120 cm (w x d x h), open front (+z), y up: side panels, back, a 3 cm bottom board,
// shelves at 38-40 and 78-80 cm, a top board at 117-120 cm, and a divider in the middle compartment.
inline std::string BookcaseObj() {
  ObjWriter w;
  w.Material("wood");
  w.Box({0, 0, 0}, {2, 117, 30});     // left side
  w.Box({78, 0, 0}, {80, 117, 30});   // right side
  w.Box({2, 0, 0}, {78, 117, 2});     // back
  w.Box({2, 0, 2}, {78, 3, 30});      // bottom board
  w.Box({2, 38, 2}, {78, 40, 30});    // shelf
  w.Box({2, 78, 2}, {78, 80, 30});    // shelf
  w.Box({0, 117, 0}, {80, 120, 30});  // top
  w.Material("painted");
  w.Box({39, 40, 2}, {41, 78, 30});   // divider
  return w.Text("bookcase.mtl");
}

// One closed box 40 x 50 x 60 (x, y, z), its origin off-centre.
inline std::string CubeObj() {
  ObjWriter w;
  w.Material("red");
  w.Box({10, -5, 0}, {50, 45, 60});
  return w.Text("cube.mtl");
}

// A PNG of w x h pixels of one colour.
inline std::string SolidPng(int w, int h, unsigned char r, unsigned char g, unsigned char b) {
  std::vector<unsigned char> pixels;
  for (int i = 0; i < w * h; ++i) pixels.insert(pixels.end(), {r, g, b});
  std::string out;
  stbi_write_png_to_func([](void* context, void* data, int size) { static_cast<std::string*>(context)->append(static_cast<char*>(data), size); },
                         &out, w, h, 3, pixels.data(), w * 3);
  return out;
}

// The catalog, as Latin-1 bytes: comments, a continued line, a \u escape and a raw Latin-1 byte.
inline std::string FixtureCatalog() {
  return "# PluginFurnitureCatalog.properties of a test library\n"
         "! another comment style\n"
         "id=Test#Library\n"
         "license=Creative Commons Attribution 3.0 license  Copyright \xA9 the villa tests\n"
         "\n"
         "id#1=Test#chest\nname#1=Toy chest\ncategory#1=Bedroom\nmodel#1=/testlib/cube/cube.obj\n"
         "width#1=80\ndepth#1=60\nheight#1=50\ncreator#1=Jane Doe\ndoorOrWindow#1=false\n"
         "id#2=Test#bookcase\nname#2=Book\\\n     case\ncategory#2=Living room\ntags#2=Shelves, Bookshelf\n"
         "model#2=/testlib/bookcase/bookcase.obj\nwidth#2=80\ndepth#2=30\nheight#2=120\ndropOnTopElevation#2=80\n"
         "creator#2=Jane Doe\n"
         "id#3=Test#mug\nname#3=Caf\\u00e9 mug\ncategory#3=Kitchen\nmodel#3=/testlib/cube/cube.obj\n"
         "width#3=8\ndepth#3=8\nheight#3=10\ncreator#3=Ren\xE9\n"
         "id#4=Test#wallLight\nname#4=Wall light\ncategory#4=Lights\nmodel#4=/testlib/cube/cube.obj\n"
         "width#4=20\ndepth#4=15\nheight#4=30\nelevation#4=140\ncreator#4=Jane Doe\n"
         "id#5=Test#hanging\nname#5=Hanging light\ncategory#5=Lights\nmodel#5=/testlib/cube/cube.obj\n"
         "width#5=40\ndepth#5=40\nheight#5=50\nelevation#5=200\ncreator#5=Jane Doe\n"
         "id#6=Test#door\nname#6=Front door\ncategory#6=Doors and windows\nmodel#6=/testlib/cube/cube.obj\n"
         "width#6=90\ndepth#6=10\nheight#6=210\ndoorOrWindow#6=true\ncreator#6=Jane Doe\n"
         "id#7=Test#stairs\nname#7=Spiral staircase\ncategory#7=Staircases\nmodel#7=/testlib/cube/cube.obj\n"
         "width#7=150\ndepth#7=150\nheight#7=300\nstaircaseCutOutShape#7=M0,0 L1,0 L1,1 z\ncreator#7=Jane Doe\n"
         "id#8=Test#rug\nname#8=Rug\ncategory#8=Living room\nmodel#8=/testlib/rug/rug.obj\n"
         "width#8=200\ndepth#8=140\nheight#8=1\ncreator#8=Jane Doe\n"
         "id#9=Test#broken\nname#9=Chair\ncategory#9=Living room\nmodel#9=/testlib/broken/broken.obj\n"
         "width#9=45\ndepth#9=50\nheight#9=90\ncreator#9=Jane Doe\n"
         "id#10=Test#noWidth\nname#10=Table\ncategory#10=Living room\nmodel#10=/testlib/cube/cube.obj\n"
         "depth#10=80\nheight#10=75\n"
         "id#11=Test#rotated\nname#11=Side table\ncategory#11=Living room\nmodel#11=/testlib/zup/zup.obj\n"
         "width#11=40\ndepth#11=60\nheight#11=50\nmodelRotation#11=1 0 0 0 0 1 0 -1 0\ncreator#11=Jane Doe\n"
         // A small thing of many triangles: over its category's budget (issue 31).
         "id#12=Test#vase\nname#12=Vase\ncategory#12=Living room\nmodel#12=/testlib/rug/rug.obj\n"
         "width#12=30\ndepth#12=30\nheight#12=1\ncreator#12=Jane Doe\n";
}

inline ZipEntries FixtureEntries() {
  ObjWriter rug;
  rug.Material("wool");
  rug.Grid(200, 0, 40);  // 3,200 triangles, flat
  ObjWriter zup;         // the cube authored z up: 40 wide (x), 60 deep (y), 50 high (z)
  zup.Material("red");
  zup.Box({0, 0, 0}, {40, 60, 50});
  return {
      {"PluginFurnitureCatalog.properties", FixtureCatalog()},
      {"testlib/cube/cube.obj", CubeObj()},
      {"testlib/cube/cube.mtl", "newmtl red\nKd 1 0 0\nd 1\n"},
      {"testlib/bookcase/bookcase.obj", BookcaseObj()},
      {"testlib/bookcase/bookcase.mtl", "newmtl wood\nKd 0.6 0.4 0.2\nnewmtl painted\nKd 0.8 0.8 0.8\nmap_Kd -s 1 1 1 blue.png\n"},
      {"testlib/bookcase/blue.png", SolidPng(4, 4, 0, 0, 255)},
      {"testlib/rug/rug.obj", rug.Text("")},
      {"testlib/broken/broken.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 99\n"},
      {"testlib/zup/zup.obj", zup.Text("cube.mtl")},
      {"testlib/zup/cube.mtl", "newmtl red\nKd 1 0 0\n"},
  };
}

// Writes TestLib.sh3f into `dir` and returns its path.
inline std::filesystem::path WriteFixtureLibrary(const std::filesystem::path& dir, bool deflate = true) {
  std::filesystem::create_directories(dir);
  std::filesystem::path file = dir / "TestLib.sh3f";
  (void)WriteFileAtomic(file, ZipBytes(FixtureEntries(), deflate));
  return file;
}

// A fresh, empty folder under the system's temporary folder.
inline std::filesystem::path FreshDir(const std::string& name) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / ("villa_assets_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace villa::test

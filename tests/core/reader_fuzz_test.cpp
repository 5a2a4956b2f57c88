// SPDX-License-Identifier: LGPL-2.1-or-later
// Inputs the fuzzers of the mesh readers (tests/fuzz) found, and the bugs behind them.
// The memory errors show only under scripts/sanitize (ASan); the plain suite checks that
// the files read as they should.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "model/model.hpp"
#include "support/error.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

// A closed tetrahedron, faces outward.
const std::string kObjTetra = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

std::string stlTetra() {
  const char* v[4] = {"0 0 0", "1 0 0", "0 1 0", "0 0 1"};
  const int f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::string s = "solid t\n";
  for (const auto& t : f) {
    s += "facet normal 0 0 0\nouter loop\n";
    for (int i : t) s += std::string("vertex ") + v[i] + "\n";
    s += "endloop\nendfacet\n";
  }
  return s + "endsolid t";  // no newline at the end
}

void expectClosedTetra(const Model& m) {
  EXPECT_EQ(m.mesh.vertices.size(), 4u);
  EXPECT_EQ(m.mesh.triangles.size(), 4u);
  EXPECT_NO_THROW(requireClosed(m));
}

std::string messageOf(const std::string& path) {
  try {
    readModel(path);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput) << e.what();
    return e.what();
  }
  ADD_FAILURE() << path << " was read";
  return "";
}

// OCCT's STL reader parsed the last line past its buffer when the file did not end with a
// newline (fuzz_stl: heap-buffer-overflow in strncasecmp). It now reads a copy ending with
// one, made in the temporary folder and removed again.
TEST(ReaderFuzz, AsciiStlWithoutFinalNewline) {
  test::TempDir dir, tmp;
  const char* old = std::getenv("TMPDIR");
  const std::string saved = old ? old : "";
  setenv("TMPDIR", tmp.file("").c_str(), 1);
  expectClosedTetra(readModel(dir.write("tetra.stl", stlTetra())));
  // The input fuzz_stl found: a one-character last line.
  EXPECT_NE(messageOf(dir.write("crash.stl", "sol\227\233\337\213e   tra\n ")).find("crash.stl"),
            std::string::npos);
  old ? setenv("TMPDIR", saved.c_str(), 1) : unsetenv("TMPDIR");
  EXPECT_TRUE(std::filesystem::is_empty(tmp.file(""))) << "the temporary copy was left behind";
}

std::string binaryStl(uint32_t count, int facets) {
  std::string s = "binary";  // not white space: OCCT skips that between blocks
  s.resize(80, ' ');
  for (int i = 0; i < 4; ++i) s += static_cast<char>(count >> (8 * i) & 0xff);
  const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (int k = 0; k < facets; ++k) {
    float data[12] = {0, 0, 0};
    for (int c = 0; c < 3; ++c)
      for (int x = 0; x < 3; ++x) data[3 + 3 * c + x] = v[f[k % 4][c]][x];
    s.append(reinterpret_cast<const char*>(data), sizeof data).append(2, '\0');  // little-endian floats
  }
  return s;
}

// OCCT sized a map by a binary STL's facet count before reading any facet (fuzz_stl:
// malloc of 13 GB for a 4 KB file). A count the file has no room for is refused, also in a
// second block after the first (OCCT reads on after the counted facets).
TEST(ReaderFuzz, BinaryStlCountBeyondTheFile) {
  test::TempDir dir;
  expectClosedTetra(readModel(dir.write("tetra.stl", binaryStl(4, 4))));
  EXPECT_NE(messageOf(dir.write("count.stl", binaryStl(808674676, 4)))
                .find("counts 808674676 triangles, the file has room for 4"),
            std::string::npos);
  EXPECT_NE(messageOf(dir.write("second.stl", binaryStl(4, 4) + "\n" + binaryStl(1000000, 1)))
                .find("header at byte 285"),
            std::string::npos);
}

// OCCT's OBJ reader parsed the last line past its buffer too (fuzz_obj: heap-buffer-overflow
// in strtol); valgrind then showed two more faults in it, below. OBJ is now read by our own
// reader (model/read_obj.cpp).
TEST(ReaderFuzz, ObjWithoutFinalNewline) {
  test::TempDir dir;
  expectClosedTetra(readModel(dir.write("tetra.obj", kObjTetra.substr(0, kObjTetra.size() - 1))));
  EXPECT_NE(messageOf(dir.write("crash.obj", "v 0 0 0\nf 4")).find("line 2: face vertex 4 does not exist"),
            std::string::npos);
}

// RWObj wrote past a vector of 1024 corners for a face with more.
TEST(ReaderFuzz, ObjFaceOfManyCorners) {
  test::TempDir dir;
  std::string obj = "v 0 0 1\n";
  const int n = 1100;
  for (int k = 0; k < n; ++k)
    obj += "v " + std::to_string(std::cos(2 * M_PI * k / n)) + " " +
           std::to_string(std::sin(2 * M_PI * k / n)) + " 0\n";
  std::string base = "f", fan;
  for (int k = n; k >= 1; --k) base += " " + std::to_string(k + 1);  // the base, seen from below
  for (int k = 1; k <= n; ++k) fan += "f 1 " + std::to_string(k + 1) + " " + std::to_string(k % n + 2) + "\n";
  const Model m = readModel(dir.write("cone.obj", obj + base + "\n" + fan));
  EXPECT_EQ(m.mesh.triangles.size(), size_t(2 * n - 2));
  EXPECT_NO_THROW(requireClosed(m));
}

// RWObj joins a line ending in '\' with the next; a '\' as the last byte of its 4 KiB read
// buffer, followed by a newline, shrank a vector below empty (std::bad_alloc escaped
// readModel). Continuations still work.
TEST(ReaderFuzz, ObjContinuationAtReadBoundary) {
  test::TempDir dir;
  std::string obj = kObjTetra + "# " + std::string(4095 - kObjTetra.size() - 3, 'x') + "\n";
  ASSERT_EQ(obj.size(), 4095u);
  obj += "\\\nv 0 0 0\nf 1 \\\n 5 2\n";  // a vertex and a face continued onto a next line
  const Model m = readModel(dir.write("boundary.obj", obj));
  EXPECT_EQ(m.mesh.triangles.size(), 4u);  // vertex 5 is vertex 1: "f 1 5 2" is welded away
  EXPECT_NO_THROW(requireClosed(m));
}

// What the OCCT reader accepted still reads: slashes, negative indices, other statements.
TEST(ReaderFuzz, ObjStatementsAndCornerForms) {
  test::TempDir dir;
  const std::string obj = "# comment\nmtllib none.mtl\no tetra\ng g1\ns off\n" +
                          kObjTetra.substr(0, kObjTetra.find('f')) +
                          "vt 0 0\nvt 1 0\nvn 0 0 -1\nusemtl red\nf 1/1/1 3/2/1 2/1/1\nf -4//1 -3//1 "
                          "-1//1\nf 1/1 4/2 3/1\r\nf 2 3 4 # last\n";
  expectClosedTetra(readModel(dir.write("forms.obj", obj)));
  // A quad is fanned into two triangles.
  const Model quad = readModel(dir.write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"));
  EXPECT_EQ(quad.mesh.triangles.size(), 2u);
}

TEST(ReaderFuzz, BadObjStatementsAreNamedByLine) {
  test::TempDir dir;
  const std::string head = kObjTetra.substr(0, kObjTetra.find('f'));  // 4 vertices
  const struct {
    const char* name;
    std::string content;
    const char* fragment;
  } cases[] = {
      {"range.obj", head + "f 2 3 99\n", "line 5: face vertex 99 does not exist (4 vertices read so far)"},
      {"zero.obj", head + "f 0 3 4\n", "line 5: face vertex 0 does not exist"},
      {"back.obj", head + "f -5 1 2\n", "line 5: face vertex -5 does not exist"},
      {"word.obj", head + "f 2 x 4\n", "line 5: \"x\" is not a vertex index"},
      {"two.obj", head + "f 1 2\n", "line 5: a face needs at least 3 vertices"},
      {"vertex.obj", "v 1 zero 0\n", "line 1: a vertex needs three numbers"},
      {"short.obj", "v 1 2\n", "line 1: a vertex needs three numbers"},
      {"huge.obj", "v 1e999 0 0\n", "line 1: a vertex needs three numbers"},
      {"nan.obj", "v nan 0 0\n" + kObjTetra.substr(kObjTetra.find('\n') + 1),
       "vertex 1 has a NaN or infinite"},
      {"faceless.obj", head, "no triangles could be read"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string message = messageOf(dir.write(c.name, c.content));
    EXPECT_NE(message.find(c.fragment), std::string::npos) << message;
    EXPECT_NE(message.find(c.name), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace sliceform

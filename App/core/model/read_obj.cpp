// SPDX-License-Identifier: LGPL-2.1-or-later
// A small reader for Wavefront OBJ meshes: vertex positions ("v") and faces ("f"), a face
// naming a missing vertex refused by line. Texture coordinates, normals, groups and
// materials do not matter to a sliceform and are skipped. Polygons are fanned into
// triangles, as the OFF reader does.
//
// OCCT 7.6's reader (RWObj) is not used: on hostile files it reads and writes outside its
// buffers (fuzzing, then valgrind on the plain build): a last line without a newline is
// parsed past its end, a face of more than 1024 corners writes past a vector, and a '\'
// continuation at its 4 KiB read boundary shrinks a vector below empty (std::bad_alloc).
#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "model/model.hpp"
#include "model/words.hpp"
#include "support/error.hpp"

namespace sliceform {
Mesh readObj(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw Error(ErrorKind::BadInput, path + ": cannot open the file");
  long number = 0;  // of the line being read
  auto fail = [&](long line, const std::string& what) {
    return Error(ErrorKind::BadInput, path + ": line " + std::to_string(line) + ": " + what);
  };
  Mesh mesh;
  std::string statement, next;
  std::vector<uint32_t> corners;
  while (std::getline(file, statement)) {
    const long first = ++number;
    // A '\' ending a line continues the statement on the next line.
    auto continued = [&] {
      while (!statement.empty() && statement.back() == '\r') statement.pop_back();
      return !statement.empty() && statement.back() == '\\';
    };
    while (continued()) {
      statement.back() = ' ';
      if (!std::getline(file, next)) break;
      statement += next;
      ++number;
    }
    const std::vector<std::string_view> words = wordsOf(statement);
    if (words.empty()) continue;
    if (words[0] == "v") {
      // x y z, then maybe w or a colour: only the position matters.
      Vec3 v;
      if (words.size() < 4 || !parseNumber(words[1], v.x) || !parseNumber(words[2], v.y) ||
          !parseNumber(words[3], v.z))
        throw fail(first, "a vertex needs three numbers");
      if (mesh.vertices.size() >= UINT32_MAX) throw fail(first, "more vertices than can be indexed");
      mesh.vertices.push_back(v);
    } else if (words[0] == "f") {
      // Corners are v, v/vt, v/vt/vn or v//vn; 1-based, negative counts back from the
      // last vertex read so far.
      corners.clear();
      const auto count = static_cast<long long>(mesh.vertices.size());
      for (size_t k = 1; k < words.size(); ++k) {
        long long index = 0;
        if (!parseNumber(words[k].substr(0, words[k].find('/')), index))
          throw fail(first, "\"" + std::string(words[k]) + "\" is not a vertex index");
        const long long resolved = index < 0 ? count + 1 + index : index;
        if (resolved < 1 || resolved > count)
          throw fail(first, "face vertex " + std::to_string(index) + " does not exist (" +
                                std::to_string(count) + " vertices read so far)");
        corners.push_back(static_cast<uint32_t>(resolved - 1));
      }
      if (corners.size() < 3) throw fail(first, "a face needs at least 3 vertices");
      for (size_t k = 1; k + 1 < corners.size(); ++k)
        mesh.triangles.push_back({corners[0], corners[k], corners[k + 1]});
    }
  }
  if (file.bad()) throw Error(ErrorKind::BadInput, path + ": reading the file failed");
  return mesh;
}

}  // namespace sliceform

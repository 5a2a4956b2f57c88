// SPDX-License-Identifier: LGPL-2.1-or-later
// A small reader for Geomview OFF files ("OFF", counts, vertices, faces as index lists);
// OCCT has none. Polygons are fanned into triangles.
#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "support/error.hpp"

namespace sliceform {
namespace {

// Next line with content, '#' comments removed.
bool nextLine(std::istream& in, std::string& line) {
  while (std::getline(in, line)) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") != std::string::npos) return true;
  }
  return false;
}

}  // namespace

Mesh readOff(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw Error(ErrorKind::BadInput, path + ": cannot open the file");
  auto fail = [&](const std::string& what) { return Error(ErrorKind::BadInput, path + ": " + what); };

  std::string line;
  if (!nextLine(file, line)) throw fail("the file is empty");
  std::istringstream header(line);
  std::string magic;
  header >> magic;
  if (magic != "OFF") throw fail("not an OFF file (it does not start with \"OFF\")");
  long long nv = -1, nf = -1, ne = 0;
  if (!(header >> nv >> nf)) {
    if (!nextLine(file, line)) throw fail("the vertex and face counts are missing");
    std::istringstream counts(line);
    if (!(counts >> nv >> nf)) throw fail("cannot read the vertex and face counts");
    counts >> ne;
  }
  // A face needs 3 indices of at least 2 characters each; more than that cannot be in a file.
  if (nv < 0 || nf < 0 || nv > (1ll << 31) || nf > (1ll << 31))
    throw fail("implausible counts: " + std::to_string(nv) + " vertices, " + std::to_string(nf) + " faces");

  Mesh mesh;
  mesh.vertices.reserve(static_cast<size_t>(std::min<long long>(nv, 1 << 24)));
  for (long long i = 0; i < nv; ++i) {
    if (!nextLine(file, line))
      throw fail("the file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    std::istringstream in(line);
    Vec3 v;
    if (!(in >> v.x >> v.y >> v.z)) throw fail("vertex " + std::to_string(i + 1) + " is not three numbers");
    mesh.vertices.push_back(v);
  }
  for (long long f = 0; f < nf; ++f) {
    if (!nextLine(file, line))
      throw fail("the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    std::istringstream in(line);
    long long n = 0;
    if (!(in >> n) || n < 3) throw fail("face " + std::to_string(f + 1) + " has fewer than 3 vertices");
    std::vector<uint32_t> ids;
    for (long long k = 0; k < n; ++k) {
      long long id = -1;
      if (!(in >> id)) throw fail("face " + std::to_string(f + 1) + " lists fewer indices than it says");
      if (id < 0 || id >= nv)
        throw fail("face " + std::to_string(f + 1) + " uses vertex " + std::to_string(id) + ", outside 0.." +
                   std::to_string(nv - 1));
      ids.push_back(static_cast<uint32_t>(id));
    }
    for (size_t k = 1; k + 1 < ids.size(); ++k) mesh.triangles.push_back({ids[0], ids[k], ids[k + 1]});
  }
  return mesh;
}

}  // namespace sliceform

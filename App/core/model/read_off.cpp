// SPDX-License-Identifier: LGPL-2.1-or-later
// A reader for Geomview's OFF family (OCCT has none): the keyword [ST][C][N]OFF, which
// Geomview makes optional, then the counts, the vertices and the faces. A sliceform needs
// positions and faces only, so the columns after a vertex's x y z (normal, colour, texture
// coordinates, in that order) are skipped unchecked, and so is a face's colour (0 to 4
// numbers after its indices). A face's colour runs to the end of its line, so the file is
// read line by line; '#' starts a comment anywhere. 4OFF and nOFF (vertices of another
// dimension) and binary OFF are refused by name. Polygons are fanned into triangles.
#include <algorithm>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "model/model.hpp"
#include "model/words.hpp"
#include "support/error.hpp"

namespace sliceform {
namespace {

// The words of the file's lines that have any, with their line numbers.
class OffLines {
 public:
  explicit OffLines(std::istream& in) : in_(in) {}
  // The next line with words; false at the end of the file. The words live until the next call.
  bool next(std::vector<std::string_view>& words) {
    while (std::getline(in_, line_)) {
      ++number_;
      words = wordsOf(line_);
      if (!words.empty()) return true;
    }
    return false;
  }
  long number() const { return number_; }

 private:
  std::istream& in_;
  std::string line_;
  long number_ = 0;
};

// The prefixes of a keyword "[ST][C][N][4][n]OFF"; `valid` false for any other word.
struct Keyword {
  bool valid = false, fourD = false, nDim = false;
};

Keyword parseKeyword(std::string_view word) {
  Keyword k;
  if (word.size() < 3 || word.substr(word.size() - 3) != "OFF") return k;
  word.remove_suffix(3);
  auto take = [&](std::string_view prefix) {
    if (word.substr(0, prefix.size()) != prefix) return false;
    word.remove_prefix(prefix.size());
    return true;
  };
  take("ST");
  take("C");
  take("N");
  k.fourD = take("4");
  k.nDim = take("n");
  k.valid = word.empty();
  return k;
}

}  // namespace

Mesh readOff(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw Error(ErrorKind::BadInput, path + ": cannot open the file");
  OffLines lines(file);
  auto fail = [&](const std::string& what) {
    return Error(ErrorKind::BadInput, path + ": line " + std::to_string(lines.number()) + ": " + what);
  };
  auto failAtEnd = [&](const std::string& what) { return Error(ErrorKind::BadInput, path + ": " + what); };

  std::vector<std::string_view> words;
  if (!lines.next(words)) throw failAtEnd("the file is empty (nothing but comments and blank lines)");
  size_t counts = 0;  // where the counts start in `words`
  long long number = 0;
  if (!parseNumber(words[0], number)) {
    const std::string keyword(words[0]);
    const Keyword k = parseKeyword(keyword);
    if (!k.valid)
      throw fail(
          "not an OFF file (it does not start with \"OFF\", a variant such as \"COFF\" or \"NOFF\", "
          "or the counts)");
    if (k.fourD)
      throw fail(keyword + " files give every vertex a fourth (homogeneous or 4D) coordinate, which is not " +
                 "supported; save the mesh as plain OFF");
    if (k.nDim)
      throw fail(keyword + " files give their vertices a dimension of their own, which is not supported; " +
                 "save the mesh as plain OFF");
    if (words.size() > 1 && words[1] == "BINARY")
      throw fail("binary OFF is not supported; save the mesh as text OFF");
    counts = 1;
    if (words.size() == 1) {  // the counts are on a line of their own
      if (!lines.next(words)) throw failAtEnd("the vertex and face counts are missing");
      counts = 0;
    }
  }
  // The edge count that may follow is not used (Geomview does not check it either).
  long long nv = -1, nf = -1;
  if (words.size() < counts + 2 || !parseNumber(words[counts], nv) || !parseNumber(words[counts + 1], nf))
    throw fail("cannot read the vertex and face counts");
  // A face needs 3 indices of at least 2 characters each; more than that cannot be in a file.
  if (nv < 0 || nf < 0 || nv > (1ll << 31) || nf > (1ll << 31))
    throw fail("implausible counts: " + std::to_string(nv) + " vertices, " + std::to_string(nf) + " faces");

  Mesh mesh;
  mesh.vertices.reserve(static_cast<size_t>(std::min<long long>(nv, 1 << 24)));
  for (long long i = 0; i < nv; ++i) {
    if (!lines.next(words))
      throw failAtEnd("the file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    Vec3 v;
    if (words.size() < 3 || !parseNumber(words[0], v.x) || !parseNumber(words[1], v.y) ||
        !parseNumber(words[2], v.z))
      throw fail("vertex " + std::to_string(i + 1) + " is not three numbers (x y z)");
    mesh.vertices.push_back(v);
  }
  std::vector<uint32_t> ids;
  for (long long f = 0; f < nf; ++f) {
    const std::string face = "face " + std::to_string(f + 1);
    if (!lines.next(words))
      throw failAtEnd("the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    long long n = 0;
    if (!parseNumber(words[0], n)) throw fail(face + " does not start with its number of vertices");
    if (n < 3) throw fail(face + " has fewer than 3 vertices");
    if (static_cast<long long>(words.size()) - 1 < n)
      throw fail(face + " lists fewer indices than it says (" + std::to_string(n) + ")");
    ids.clear();
    for (long long k = 1; k <= n; ++k) {
      long long id = -1;
      if (!parseNumber(words[k], id))
        throw fail(face + ": \"" + std::string(words[k]) + "\" is not a vertex index");
      if (id < 0 || id >= nv)
        throw fail(face + " uses vertex " + std::to_string(id) + ", outside 0.." + std::to_string(nv - 1));
      ids.push_back(static_cast<uint32_t>(id));
    }
    // What follows the indices is the face's colour: a colormap index, or RGB[A].
    const size_t colour = words.size() - 1 - static_cast<size_t>(n);
    for (size_t k = static_cast<size_t>(n) + 1; k < words.size(); ++k) {
      double value = 0;
      if (!parseNumber(words[k], value))
        throw fail(face + " ends in \"" + std::string(words[k]) + "\", which is not part of a colour");
    }
    if (colour > 4)
      throw fail(face + " has " + std::to_string(colour) + " numbers after its " + std::to_string(n) +
                 " indices; a colour is at most 4 (RGBA): is its vertex count right?");
    for (size_t k = 1; k + 1 < ids.size(); ++k) mesh.triangles.push_back({ids[0], ids[k], ids[k + 1]});
  }
  return mesh;
}

}  // namespace sliceform

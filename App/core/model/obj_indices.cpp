// SPDX-License-Identifier: LGPL-2.1-or-later
// OCCT's OBJ reader skips a face that names a vertex the file does not have, and the mesh
// then looks merely open. Checked first, the user hears which line is wrong.
#include <fstream>
#include <sstream>
#include <string>

#include "model/model.hpp"
#include "support/error.hpp"

namespace sliceform {

void checkObjIndices(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  long vertices = 0;
  for (long number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v") {
      ++vertices;
      continue;
    }
    if (tag != "f") continue;
    std::string corner;
    while (words >> corner) {
      long index = 0;
      try {
        index = std::stol(corner.substr(0, corner.find('/')));
      } catch (const std::exception&) {
        throw Error(ErrorKind::BadInput,
                    path + ": line " + std::to_string(number) + ": \"" + corner + "\" is not a vertex index");
      }
      // 1-based; negative counts back from the last vertex read so far.
      const long resolved = index < 0 ? vertices + 1 + index : index;
      if (resolved < 1 || resolved > vertices)
        throw Error(ErrorKind::BadInput, path + ": line " + std::to_string(number) + ": face vertex " +
                                             std::to_string(index) + " does not exist (" +
                                             std::to_string(vertices) + " vertices read so far)");
    }
  }
}

}  // namespace sliceform

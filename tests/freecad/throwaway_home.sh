# SPDX-License-Identifier: LGPL-2.1-or-later
# Sourced by the FreeCAD test scripts: installs the workbench from the build folder $1 into
# a fresh HOME (removed on exit) and points HOME and the XDG folders there, so a test run
# never touches the user's FreeCAD settings or Mod folder. Sets $build, $here and $home.
build=$(cd "$1" && pwd)
here=$(cd "$(dirname "${BASH_SOURCE[1]}")" && pwd)
home=$(mktemp -d)
trap 'rm -rf "$home"' EXIT
cmake --install "$build" --prefix "$home/.local/share/FreeCAD/Mod/Sliceform" >/dev/null
export HOME="$home" XDG_DATA_HOME="$home/.local/share" XDG_CONFIG_HOME="$home/.config" XDG_CACHE_HOME="$home/.cache"

#!/usr/bin/env bash
# Makes FreeCAD's libarea (the Python module `area`, the pocketing library of FreeCAD's CAM and
# HeeksCNC) importable from Python 3.11, without installing anything system-wide:
#
#   bench/libarea/fetch.sh            unpack into target/libarea (the default)
#   LIBAREA_DIR=/some/dir bench/libarea/fetch.sh
#
# Steps: `apt-get download libfreecad-python3-0.20` (Debian 12's FreeCAD 0.20, about 34 MB; the
# package holds area.so and libarea-native.so, built for Python 3.11), `dpkg -x` into the folder,
# then a probe import with LD_LIBRARY_PATH set to the folder's lib directory. area.so needs only
# libarea-native.so (in the same package), libpython3.11 and the C/C++ runtime: no other package.
# Nothing downloaded is committed (target/ is ignored). Prints the two lines to export.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
dir=${LIBAREA_DIR:-$here/../../target/libarea}
mkdir -p "$dir/debs"
dir=$(cd "$dir" && pwd)
lib=$dir/root/usr/lib/freecad-python3/lib
if [[ ! -f $lib/area.so ]]; then
  ( cd "$dir/debs" &&
    { ls libfreecad-python3-0.20_*.deb >/dev/null 2>&1 ||
      apt-get download libfreecad-python3-0.20 >&2 ||
      { apt-get update -qq && apt-get download libfreecad-python3-0.20 >&2; }; } )
  for d in "$dir"/debs/*.deb; do dpkg -x "$d" "$dir/root"; done
fi
py=${PYTHON:-python3.11}
LD_LIBRARY_PATH=$lib PYTHONPATH=$lib "$py" -c 'import area; area.Area().MakePocketToolpath' ||
  { echo "fetch.sh: area does not import with $py (it is built for Python 3.11)" >&2; exit 1; }
echo "export LD_LIBRARY_PATH=$lib"
echo "export PYTHONPATH=$lib"

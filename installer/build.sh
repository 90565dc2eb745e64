#!/usr/bin/env bash
# Builds Fresa's native application image with jpackage (target/installer/Fresa/bin/Fresa),
# and a .deb package too where dpkg-deb and fakeroot exist.
#   installer/build.sh [--app-image-only]
set -euo pipefail
cd "$(dirname "$0")/.."
only_image=${1:-}
[ -f target/fresa.jar ] || mvn -q -B -ntp -DskipTests package
command -v jpackage >/dev/null 2>&1 || { echo "installer: jpackage not found (it comes with a JDK 17)" >&2; exit 2; }
version=$(sed -n 's:.*<version>\([0-9][0-9.]*\).*</version>.*:\1:p' pom.xml | head -n 1)
rm -rf target/installer
mkdir -p target/installer/input
cp target/fresa.jar target/installer/input/
common=(--name Fresa --app-version "${version:-0.1.0}" --input target/installer/input --main-jar fresa.jar
        --main-class org.fresa.app.Main --dest target/installer
        --description "CAM for process planners: STEP-NC to robot, pocket milling, sheet cutting, shoe soles"
        --vendor "Fresa" --java-options "-Xmx2g")
jpackage --type app-image "${common[@]}"
echo "installer: app image in target/installer/Fresa"
if [ "$only_image" != "--app-image-only" ] && command -v dpkg-deb >/dev/null 2>&1 && command -v fakeroot >/dev/null 2>&1; then
  jpackage --type deb "${common[@]}" --linux-shortcut --linux-menu-group Development
  echo "installer: $(ls target/installer/*.deb)"
fi

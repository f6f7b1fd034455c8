#!/usr/bin/env bash
# Sets sandpic up on a Debian machine: installs the Debian packages it needs
# (as root, or through sudo), then configures and builds into build/.
# --tests also installs Chromium, which the validation report's test opens
# headless (290 MB: a machine that only renders does not need it), and for
# the studio's end-to-end test (tests/e2e) Node.js and npm when `node`/`npm`
# are missing, then playwright-core from npm (npm ci, no browser download:
# it drives that Chromium); --fuzz also clang and its runtime libraries,
# which hold libFuzzer (.ci/fuzz).
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(g++ cmake make pkgconf libeigen3-dev libopencv-dev libpng-dev libtbb-dev libbullet-dev libcpp-httplib-dev
          libgtest-dev libcli11-dev nlohmann-json3-dev
          lammps openmpi-bin)  # --mode lammps runs LAMMPS's lmp (GRANULAR), on more ranks under mpirun
TESTS=0
for arg in "$@"; do
  case "$arg" in
    --tests)
      TESTS=1
      PACKAGES+=(chromium)
      # Any Node.js on PATH will do (>= 18: Debian 12's, or nodesource's with its own npm).
      command -v node >/dev/null || PACKAGES+=(nodejs)
      command -v npm >/dev/null || PACKAGES+=(npm) ;;
    --fuzz) PACKAGES+=(clang libclang-rt-14-dev) ;;
    *) echo "setup: unknown option $arg (--tests or --fuzz)" >&2; exit 2 ;;
  esac
done
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" = 0 ] || SUDO=sudo
  echo "setup: installing ${missing[*]}" >&2
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}" >/dev/null
fi

if [ "$TESTS" = 1 ]; then
  echo "setup: npm ci in tests/e2e (playwright-core; no browser download)" >&2
  (cd tests/e2e && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error)
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"

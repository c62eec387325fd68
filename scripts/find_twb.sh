# Sourced by the study scripts: find_twb SCRIPT_NAME sets $twb to the binary given with
# --twb, else build-rel/twb, else build/twb, else the installed twb on PATH (README), and
# exits 2 when there is none.
# Needs $root (the repository) and $twb (empty or the --twb value).
find_twb() {
  if [ -z "$twb" ]; then
    for candidate in "$root/build-rel/twb" "$root/build/twb"; do
      if [ -x "$candidate" ]; then twb=$candidate; break; fi
    done
    [ -n "$twb" ] || twb=$(command -v twb || true)
  fi
  if [ -z "$twb" ] || [ ! -x "$twb" ]; then
    echo "$1: no twb binary${twb:+ at '$twb'}; build it (README) or pass --twb PATH" >&2
    exit 2
  fi
}

# study_options SCRIPT_NAME USAGE_LINES ARGS...: the study scripts' options, --twb PATH
# and --out DIR (into $twb and $out, whose default the script set), then find_twb. A bad
# argument or -h prints the script's usage, its comment lines USAGE_LINES (e.g. 9,12),
# and exits 2.
study_options() {
  name=$1 lines=$2
  shift 2
  while [ $# -gt 0 ]; do
    case "$1" in
      --twb) [ $# -ge 2 ] || study_usage "$lines"; twb=$2; shift 2 ;;
      --out) [ $# -ge 2 ] || study_usage "$lines"; out=$2; shift 2 ;;
      -h|--help) study_usage "$lines" ;;
      *) echo "$name: unknown argument '$1'" >&2; study_usage "$lines" ;;
    esac
  done
  find_twb "$name"
}

study_usage() {
  sed -n "$1p" "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
}

# Sourced by the study scripts: find_twb SCRIPT_NAME sets $twb to the binary given with
# --twb, else build-rel/twb, else build/twb (README), and exits 2 when there is none.
# Needs $root (the repository) and $twb (empty or the --twb value).
find_twb() {
  if [ -z "$twb" ]; then
    for candidate in "$root/build-rel/twb" "$root/build/twb"; do
      if [ -x "$candidate" ]; then twb=$candidate; break; fi
    done
  fi
  if [ -z "$twb" ] || [ ! -x "$twb" ]; then
    echo "$1: no twb binary${twb:+ at '$twb'}; build it (README) or pass --twb PATH" >&2
    exit 2
  fi
}

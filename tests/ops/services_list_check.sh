#!/usr/bin/env bash
# deploy/services.list is the one list of programs: it parses, is in priority order,
# names every service with a main.cpp (and only those), marks robot_json exactly the
# services that take --robot, matches refloc-status's default --expect, and deploy/refloc
# writes one supervisord [program:*] section per entry with the list's priority.
#   services_list_check.sh REPO_ROOT
set -euo pipefail
repo="$(cd "$1" && pwd)"
fail() { echo "FAIL: $*" >&2; exit 1; }
list="$repo/deploy/services.list"
refloc="$repo/deploy/refloc"
# Service folders with a main.cpp that are not deployed programs, and why.
declare -A not_deployed=(
  [lms100_emulator]="standalone emulated LMS100 for bench tests; in the stack robot_sim runs it")

mapfile -t programs < <("$refloc" list) || fail "deploy/refloc list"
mapfile -t services < <("$refloc" list --services)
[ "${programs[0]}" = lcm-logger ] || fail "lcm-logger should be listed first (priority 10): ${programs[*]}"

last=0
while read -r name priority _; do
  [ "$priority" -ge "$last" ] || fail "$list: $name (priority $priority) after priority $last: keep the list in start order"
  last=$priority
done < <(grep -vE '^\s*(#|$)' "$list")

for s in "${services[@]}"; do
  [ -f "$repo/services/$s/main.cpp" ] || fail "$list names $s, but services/$s/main.cpp does not exist"
done
for main in "$repo"/services/*/main.cpp; do
  s="$(basename "$(dirname "$main")")"
  [ -n "${not_deployed[$s]:-}" ] && continue
  printf '%s\n' "${services[@]}" | grep -qxF "$s" || fail "services/$s/main.cpp is not in $list"
done

for s in "${services[@]}"; do
  listed="$(awk -v n="$s" '$1 == n {print $4}' "$list")"
  takes=no
  grep -qE 'add_robot_option|"--robot"' "$repo/services/$s/main.cpp" && takes=yes
  [ "$listed" = "$takes" ] ||
    fail "$list: $s robot_json=$listed, but its main.cpp $([ $takes = yes ] && echo takes || echo "does not take") --robot"
done

# refloc-status expects every service by default: the same set as the list.
status_default="$(awk '/std::vector<std::string> expected\{/ {on = 1} on {print} on && /\};/ {exit}' \
  "$repo/tools/refloc-status/main.cpp" | grep -o '"[a-z_0-9-]*"' | tr -d '"' | sort | tr '\n' ' ')"
listed_services="$(printf '%s\n' "${services[@]}" | sort | tr '\n' ' ')"
[ "$status_default" = "$listed_services" ] ||
  fail "refloc-status's default --expect ($status_default) is not the list's services ($listed_services)"

# The robot profile writes a section for every program except the simulation-only ones;
# --sim writes all of them.
mapfile -t real_programs < <("$refloc" list --real)
check_conf() {
  local conf="$1" label="$2"; shift 2
  local p priority section
  for p in "$@"; do
    priority="$(awk -v n="$p" '$1 == n {print $2}' "$list")"
    section="$(awk -v h="[program:$p]" '$0 == h {on = 1; next} /^\[/ {on = 0} on' <<<"$conf")"
    [ -n "$section" ] || fail "supervisor-conf $label has no [program:$p]"
    grep -qxF "priority=$priority" <<<"$section" || fail "[program:$p] ($label) lacks priority=$priority"
    grep -qxF "command=$repo/deploy/refloc exec $p" <<<"$section" || fail "[program:$p] ($label) does not run deploy/refloc exec $p"
  done
  [ "$(grep -c '^\[program:' <<<"$conf")" -eq $# ] || fail "supervisor-conf $label has extra sections"
}
check_conf "$("$refloc" supervisor-conf)" "(robot profile)" "${real_programs[@]}"
check_conf "$("$refloc" supervisor-conf --sim)" "--sim" "${programs[@]}"
[ ${#real_programs[@]} -lt ${#programs[@]} ] || fail "list --real drops no simulation-only program"

# A malformed line is an error naming the file and line.
bad="$(mktemp /tmp/refloc_services_list.XXXXXX)"
trap 'rm -f "$bad"' EXIT
printf 'lcm-logger 10 no no -\npose_solver forty no yes -\n' >"$bad"
if out="$(REFLOC_SERVICES_LIST="$bad" "$refloc" list 2>&1)"; then fail "a malformed list was accepted: $out"; fi
grep -qF "$bad:2:" <<<"$out" || fail "the error does not name the line: $out"
echo "PASS: ${#programs[@]} programs (${programs[*]}); robot_json matches --robot; supervisor-conf matches (robot profile: ${#real_programs[@]}, --sim: ${#programs[@]})"

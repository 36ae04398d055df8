#!/usr/bin/env bash
# lcm-spy with the refloc message types on its class path, so every channel is
# decoded field by field. Debian's lcm-spy script fails on Java 17
# ("Unrecognized option: -Xincgc"), so java is started here directly; lcm-spy
# finds the types by scanning $CLASSPATH; jchart2d draws its detail plots.
#   deploy/lcm-spy.sh [--lcm-url URL] [other lcm-spy options]
set -euo pipefail

root="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)"
build="${REFLOC_BUILD:-$root/build}"
jar="${REFLOC_TYPES_JAR:-$build/share/java/refloc_lcmtypes.jar}"
url="${LCM_DEFAULT_URL:-udpm://239.255.76.67:7667?ttl=0}"
lcm_jar=/usr/share/java/lcm.jar
jchart_jar=/usr/share/java/jchart2d.jar

passthrough=()
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help)
      echo "usage: $0 [--lcm-url URL] [lcm-spy options]"
      echo "  types jar: $jar (REFLOC_TYPES_JAR or REFLOC_BUILD to change)"
      echo "  URL default: \$LCM_DEFAULT_URL or udpm://239.255.76.67:7667?ttl=0"
      exit 0 ;;
    --lcm-url|-l) [ $# -ge 2 ] || { echo "$0: $1 needs a URL" >&2; exit 64; }; url="$2"; shift 2 ;;
    --lcm-url=*) url="${1#--lcm-url=}"; shift ;;
    *) passthrough+=("$1"); shift ;;
  esac
done

[ -f "$lcm_jar" ] || { echo "$0: $lcm_jar missing (apt-get install liblcm-java)" >&2; exit 1; }
if [ ! -f "$jar" ]; then
  echo "$0: no types jar at $jar; build it: cmake --build $build --target refloc_lcmtypes_jar" >&2
  exit 1
fi
classpath="$lcm_jar"
if [ -f "$jchart_jar" ]; then
  classpath="$classpath:$jchart_jar"
else
  echo "$0: warning: $jchart_jar missing (apt-get install libjchart2d-java): no plots" >&2
fi
# lcm-spy prints "Found N LCM types" at start: N should be 15.
CLASSPATH="$jar" exec java -Djava.net.preferIPv4Stack=true -cp "$classpath" lcm.spy.Spy \
  --lcm-url="$url" "${passthrough[@]}"

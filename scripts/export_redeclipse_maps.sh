#!/bin/sh
# Export Red Eclipse 1.6 maps' world (octree) geometry to Wavefront OBJ: real
# Cube 2 engine levels this project was never tuned on, for measuring bake
# speed and auditing coverings beyond the shared scenes
# (docs/results/worlds.md, "Maps never seen"). The game's own `writeobj` writes
# each map, loaded in edit mode under a virtual X server with software GL.
# Not used by the tests or CI (the packages are about 860 MB).
# Usage: export_redeclipse_maps.sh OUTDIR MAP [MAP...]
# Needs: apt-get install -y redeclipse redeclipse-data xvfb xauth mesa-utils libgl1-mesa-dri
# The OBJ is y-up, in the game's units (an 8-unit editor grid); faces point
# into empty space, sky, water and glass surfaces and placed models are left out.
set -e
OUT=$1; shift
[ -n "$OUT" ] && [ $# -gt 0 ] || { echo "usage: $0 OUTDIR MAP [MAP...]" >&2; exit 2; }
mkdir -p "$OUT"
HOMEDIR=$(mktemp -d /tmp/rehome.XXXXXX)
cat > "$HOMEDIR/export.cfg" <<'CFG'
exportidx = 0
doexport = [
  if (< $exportidx (listlen $exportmaps)) [
    expm = (at $exportmaps $exportidx)
    echo (concatword "EXPORTSTART " $expm)
    mode 1 0
    map $expm
    sleep $exportwait [
      writeobj (concatword "rm_" $expm)
      echo (concatword "EXPORTDONE " $expm)
      exportidx = (+ $exportidx 1)
      doexport
    ]
  ] [ quit ]
]
CFG
MAPS="$*"
LIBGL_ALWAYS_SOFTWARE=1 SDL_AUDIODRIVER=dummy timeout $((120 + 20 * $#)) \
  xvfb-run -a -s "-screen 0 800x600x24" /usr/games/redeclipse -h"$HOMEDIR" -g -df0 -dw640 -dh480 -ss0 \
  -x"exportmaps = \"$MAPS\"; exportwait = 3000; exec export.cfg; doexport" > "$HOMEDIR/run.log" 2>&1 || true
for m in "$@"; do
  if [ -s "$HOMEDIR/rm_$m.obj" ]; then
    sed "s/^mtllib rm_$m\.mtl$/mtllib $m.mtl/" "$HOMEDIR/rm_$m.obj" > "$OUT/$m.obj"
    cp "$HOMEDIR/rm_$m.mtl" "$OUT/$m.mtl"
    echo "$m: $(grep -c '^v ' "$OUT/$m.obj") vertices, $(grep -c '^f ' "$OUT/$m.obj") faces"
  else
    echo "$m: FAILED (see $HOMEDIR/run.log)" >&2
  fi
done
echo "log: $HOMEDIR/run.log"

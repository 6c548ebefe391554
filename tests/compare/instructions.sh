#!/bin/bash
# Instructions (valgrind's callgrind "I refs") rts spends reading POV-Ray sample
# scenes and rendering them at 1x1, one thread: a load-free measure of the front
# end to put beside parse_speed.py's wall-clock ratios.
#
#   bash tests/compare/instructions.sh [RTS_BINARY] [SCENE.pov ...]
#
# Scenes are paths under /usr/share/povray-3.7/scenes (or absolute); without any,
# the ones the stop notes quote. Needs valgrind and POV-Ray's sample scenes:
#   apt-get install -y valgrind povray-examples povray-includes
set -eu
B=$(realpath "${1:-target/release/rts}")
shift || true
S=/usr/share/povray-3.7/scenes
if [ $# -eq 0 ]; then
  set -- incdemo/i_internal.pov objects/chesmsh.pov incdemo/colors.pov \
    textures/patterns/crackle3.pov textures/patterns/crackle2.pov objects/isosurfaces.pov \
    portfolio/allpat1iso.pov language/vturbulence.pov advanced/wallstucco.pov \
    advanced/landscape.pov advanced/benchmark/benchmark.pov advanced/balcony/balcony.pov \
    advanced/isocacti.pov
fi
for f in "$@"; do
  case $f in /*) p=$f ;; *) p=$S/$f ;; esac
  ir=$(cd "$(dirname "$p")" && RAYON_NUM_THREADS=1 valgrind --tool=callgrind \
    --callgrind-out-file=/dev/null "$B" render "$(basename "$p")" -W 1 -H 1 -o /dev/null -q 2>&1 |
    awk '/refs/ {print $NF}')
  echo "$f $ir"
done

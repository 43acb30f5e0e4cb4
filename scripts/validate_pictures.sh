#!/usr/bin/env bash
# The pictures of the validation atlas, called by `./ndda.sh validate`:
#
#   scripts/validate_pictures.sh NDDA_BINARY PYTHON
#
# - the gallery (doc/gallery/): the thesis's fracture examples run to their
#   end, frames at the start, the first crack, the propagation and the end
#   (scripts/plot_frames.py --auto), and stress histories
#   (scripts/plot_history.py);
# - when their scripts exist: the speed-accuracy charts
#   (scripts/speed_accuracy.py, doc/speed_accuracy/) and the stability maps
#   (scripts/stability_map.py, doc/stability/).
# Runs go to build/validation/; PYTHON must have numpy and matplotlib
# (Debian's /usr/bin/python3 with python3-numpy, python3-matplotlib).
set -euo pipefail

ndda="$1"
py="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="$(dirname "$ndda")/validation"
mkdir -p "$work" "$here/doc/gallery"

# A scene with its output in $work/NAME (graphical output every 1e-4 s).
run_scene() {
  local name="$1"
  local prm="$work/$name.prm"
  cp "$here/prm/$name.prm" "$prm"
  printf 'subsection Output\n  set Directory = %s\n  set Interval = 1e-4\nend\n' \
    "$work/$name" >> "$prm"
  echo "validate_pictures: running $name"
  (cd "$work" && "$ndda" "$prm" > "$work/$name.screen" 2>&1)
}

for name in brazilian_disc brazilian_disc_crack brazilian_disc_hole; do
  run_scene "$name"
  "$py" "$here/scripts/plot_frames.py" "$work/$name" --auto \
    --field stress_xx --out "$here/doc/gallery/$name"
  "$py" "$here/scripts/plot_frames.py" "$work/$name" --times 0 \
    --field stress_xx --mesh --out "$work/${name}_mesh"
  cp "$work/${name}_mesh_00000.png" "$here/doc/gallery/${name}_start.png"
done
"$py" "$here/scripts/plot_history.py" "$work/brazilian_disc" \
  --column "point 0 sigma_xx" --column "point 1 sigma_xx" \
  --column "Cracked edges" \
  --out "$here/doc/gallery/brazilian_disc_history.png"

if [ -f "$here/scripts/speed_accuracy.py" ]; then
  "$py" "$here/scripts/speed_accuracy.py" --ndda "$ndda" --prm-dir "$here/prm" \
    --out-dir "$here/doc/speed_accuracy" \
    --markdown "$here/doc/speed_accuracy/speed_accuracy.md"
fi
if [ -f "$here/scripts/stability_map.py" ]; then
  "$py" "$here/scripts/stability_map.py" --ndda "$ndda" --prm-dir "$here/prm" \
    --out-dir "$here/doc/stability" \
    --markdown "$here/doc/stability/stability.md"
fi

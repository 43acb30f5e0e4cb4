#!/usr/bin/env bash
# The pictures of the validation atlas, called by `./ndda.sh validate`:
#
#   scripts/validate_pictures.sh NDDA_BINARY PYTHON
#
# - the gallery (doc/gallery/, described in doc/gallery.md): every scene
#   of prm/ run to its end; PNG frames at the moments that matter
#   (scripts/plot_frames.py: --auto for the fracture scenes, chosen times
#   for the others), histories against the analytical curves
#   (scripts/plot_history.py), the stress-strain curves of the compression
#   tests and the Brazilian disc's centre stress against 2P/(pi D t)
#   (scripts/plot_load_curves.py); Kirsch's hole, cells against accuracy
#   for uniform and graded meshes (scripts/plot_cells_against_error.py,
#   from the test suite's kirsch_hole);
# - when their scripts exist: the speed-accuracy charts
#   (scripts/speed_accuracy.py, doc/speed_accuracy/), the integrators'
#   charts of the brick wall and the Brazilian disc
#   (scripts/integrator_charts.py, doc/integrators/) and the stability maps
#   (scripts/stability_map.py, doc/stability/).
# Runs go to build/validation/ (beside NDDA_BINARY); PYTHON must have numpy
# and matplotlib (Debian's /usr/bin/python3 with python3-numpy,
# python3-matplotlib). One ndda process at a time. The gallery's runs take
# about 10 minutes on two cores (the two compression tests most of it).
#
# Environment:
#   NDDA_PICTURES_ONLY_GALLERY=1  the gallery only: skip the speed-accuracy
#                                 and stability sweeps (about 45 minutes).
#   NDDA_PICTURES_REUSE_RUNS=1    do not run a scene whose output folder in
#                                 build/validation/ has a statistics file
#                                 from an earlier run: redraw only.
set -euo pipefail

ndda="$1"
py="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="$(dirname "$ndda")/validation"
gallery="$here/doc/gallery"
mkdir -p "$work" "$gallery"

# run_scene NAME [INTERVAL]: prm/NAME.prm with its output in $work/NAME,
# VTU frames every INTERVAL seconds (default: the scene's own interval).
# measure_points.txt and statistics get a row every step anyway.
run_scene() {
  local name="$1"
  local interval="${2:-}"
  local prm="$work/$name.prm"
  if [ "${NDDA_PICTURES_REUSE_RUNS:-0}" = 1 ] && [ -f "$work/$name/statistics" ]; then
    echo "validate_pictures: reusing the run of $name"
    return
  fi
  rm -rf "${work:?}/$name"
  cp "$here/prm/$name.prm" "$prm"
  {
    printf 'subsection Output\n  set Directory = %s\n' "$work/$name"
    [ -n "$interval" ] && printf '  set Interval = %s\n' "$interval"
    printf 'end\n'
  } >> "$prm"
  echo "validate_pictures: running $name"
  local start=$SECONDS
  (cd "$work" && "$ndda" "$prm" > "$work/$name.screen" 2>&1)
  echo "validate_pictures: $name took $((SECONDS - start)) s"
}

# The start of a fracture scene drawn again with the mesh (PREFIX_start.png
# of --auto replaced): the model as the thesis's configuration figures show
# it, with the pre-existing cracks. Extra arguments go to plot_frames.py.
start_with_mesh() {
  local name="$1"
  shift
  frames "$name" --times 0 --mesh --initial-cracks --out "$work/${name}_mesh" "$@"
  cp "$work/${name}_mesh_00000.png" "$gallery/${name}_start.png"
}

frames() {
  local name="$1"
  shift
  "$py" "$here/scripts/plot_frames.py" "$work/$name" "$@"
}
history() {
  local name="$1"
  shift
  "$py" "$here/scripts/plot_history.py" "$work/$name" "$@"
}
load_curve() {
  "$py" "$here/scripts/plot_load_curves.py" "$1" "$work/$2" --out "$3"
}

# d'Alembert's solution for the thesis's bar (tests/elastic_bar_wave.cc):
# a pressure pulse p(s) = P0 sin^2(pi s / T), T = 40 us, at x = 0 of a bar
# of length L = 1 m with a free end, bar speed c = sqrt(E / rho); at x the
# incident wave p(t - x/c) and the one reflected at the free end,
# p(t - (2L - x)/c), with the opposite sign in the stress:
#   v_x = (p(t - x/c) + p(t - (2L - x)/c)) / (rho c),
#   sigma_xx = -p(t - x/c) + p(t - (2L - x)/c).
bar_c="sqrt(50e9 / 2600)"
bar_pulse() { # P0 ARGUMENT
  echo "where(($2 >= 0) & ($2 <= 4e-5), $1 * sin(pi * ($2) / 4e-5)**2, 0)"
}
bar_velocity() { # P0 X
  echo "($(bar_pulse "$1" "t - $2 / $bar_c") + $(bar_pulse "$1" "t - (2 - $2) / $bar_c")) / (2600 * $bar_c)"
}
bar_stress() { # P0 X
  echo "$(bar_pulse "$1" "t - (2 - $2) / $bar_c") - $(bar_pulse "$1" "t - $2 / $bar_c")"
}

# ------------------------------------------------------------ the bar
name=elastic_bar_wave
run_scene $name 1e-5
# The moments of thesis Figure 7.5: the peak at mid-bar (133 us), the
# reflection at the free end superposed on the incident pulse (248 us),
# the reflected peak back at mid-bar (363 us).
frames $name --times 133us,248us,363us --names incident,reflection,reflected \
  --field stress_xx --stretch 8 --size 9 --out "$gallery/$name"
history $name \
  --column "point 1 v_x" --column "point 2 v_x" \
  --column "point 1 sigma_xx" --column "point 2 sigma_xx" \
  --reference-expr "$(bar_velocity 1e6 0.5)" --reference-column "point 1 v_x" \
  --reference-label "d'Alembert, x = 0.5 m" \
  --reference-expr "$(bar_velocity 1e6 0.97)" --reference-column "point 2 v_x" \
  --reference-label "d'Alembert, x = 0.97 m" \
  --reference-expr "$(bar_stress 1e6 0.5)" --reference-column "point 1 sigma_xx" \
  --reference-label "d'Alembert, x = 0.5 m" \
  --reference-expr "$(bar_stress 1e6 0.97)" --reference-column "point 2 sigma_xx" \
  --reference-label "d'Alembert, x = 0.97 m" \
  --title "elastic_bar_wave: velocity and stress against d'Alembert's solution" \
  --out "$gallery/${name}_history.png"

name=bar_spalling
run_scene $name 1e-5
frames $name --auto --field stress_xx --xlim=880,1005 --ylim=-10,40 \
  --out "$gallery/$name"
frames $name --times 250us --names reflection --field stress_xx --stretch 8 \
  --size 9 --out "$gallery/$name"
history $name \
  --column "point 2 v_x" --column "point 2 sigma_xx" \
  --reference-expr "$(bar_velocity 35e6 0.97)" --reference-column "point 2 v_x" \
  --reference-label "d'Alembert, unbroken bar" \
  --reference-expr "$(bar_stress 35e6 0.97)" --reference-column "point 2 sigma_xx" \
  --reference-label "d'Alembert, unbroken bar" \
  --mark-first-crack \
  --title "bar_spalling: the point at x = 0.97 m against d'Alembert's solution" \
  --out "$gallery/${name}_history.png"

# ------------------------------------------------- fracture specimens
name=inclined_crack_tension
run_scene $name 1e-5
frames $name --auto --out "$gallery/$name"
start_with_mesh $name
history $name \
  --column "Strain energy (J)" --column "Kinetic energy (J)" \
  --column "Cracked edges" --mark-first-crack \
  --out "$gallery/${name}_history.png"

# --auto's first crack is a single failed edge, too small to see in the
# whole specimen; the wing_cracks frame is taken near the peak of the
# stress-strain curve (in these scenes' runs, 1.7-1.9 ms), when the wing
# cracks are a few centimetres long (thesis Figures 7.22 (b), 7.25 (b)).
for name in uniaxial_compression_one_crack uniaxial_compression_two_cracks; do
  run_scene $name 5e-5
  frames $name --auto --out "$gallery/$name"
  start_with_mesh $name
  load_curve compression $name "$gallery/${name}_stress_strain.png"
done
frames uniaxial_compression_one_crack --times 1.8ms --names wing_cracks \
  --out "$gallery/uniaxial_compression_one_crack"
frames uniaxial_compression_two_cracks --times 1.7ms --names wing_cracks \
  --out "$gallery/uniaxial_compression_two_cracks"

# ---------------------------------------------------- Brazilian discs
for name in brazilian_disc brazilian_disc_crack brazilian_disc_hole; do
  run_scene $name 1e-4
  frames $name --auto --field stress_xx --out "$gallery/$name"
  start_with_mesh $name --field stress_xx
done
history brazilian_disc \
  --column "point 0 sigma_xx" --column "point 1 sigma_xx" \
  --column "Cracked edges" \
  --out "$gallery/brazilian_disc_history.png"
load_curve brazilian brazilian_disc "$gallery/brazilian_disc_centre.png"

# ------------------------------------------------------ elastic statics
name=cantilever
run_scene $name
frames $name --times 1 --names end --field stress_xx --mesh --out "$gallery/$name"

# ------------------------------------------------------------- contact
name=sliding_block
run_scene $name
frames $name --times 0,0.5,1 --names start,middle,end --out "$gallery/$name"
# The centre's slide along the 30 degree slope (down the slope positive)
# against the rigid block's g (sin a - cos a tan phi) t^2 / 2, phi = 20 deg.
history $name \
  --derived "slide along the slope|m|-(col('point 0 u_x') * cos(pi / 6) + col('point 0 u_y') * sin(pi / 6))" \
  --column "slide along the slope" \
  --reference-expr "9.81 * (sin(pi / 6) - cos(pi / 6) * tan(pi / 9)) * t**2 / 2" \
  --reference-label "rigid block: g (sin 30° - cos 30° tan 20°) t²/2" \
  --title "sliding_block: slide of the centre" \
  --out "$gallery/${name}_history.png"

name=toppling_block
run_scene $name
frames $name --times 0,0.3,0.6 --names start,middle,end --out "$gallery/$name"
# The block's rotation (anticlockwise positive) from the line between its
# two measure points, the centroid and the top downhill corner (their
# offset at the start: -0.3799038, 0.3580127 m). No analytical curve: the
# rigid block's rotation about its corner is a pendulum equation without a
# closed form (tests/toppling_block.cc integrates it; doc/validation.md).
history $name \
  --derived "rotation|rad|unwrap(arctan2(0.3580127 + col('point 1 u_y') - col('point 0 u_y'), -0.3799038 + col('point 1 u_x') - col('point 0 u_x'))) - arctan2(0.3580127, -0.3799038)" \
  --column "rotation" --column "point 0 u_x" --column "point 0 u_y" \
  --title "toppling_block: rotation and centroid displacement" \
  --out "$gallery/${name}_history.png"

name=block_drop
run_scene $name
frames $name --times 0,0.32,0.64 --names start,impact,rebound --out "$gallery/$name"
# The centre's height against free fall from 0.75 m until the block's
# bottom (0.25 m below the centre) reaches the fixed block at y = 0.
history $name \
  --derived "height of the centre|m|0.75 + col('point 0 u_y')" \
  --column "height of the centre" \
  --reference-expr "where(t <= sqrt(2 * 0.5 / 9.81), 0.75 - 9.81 * t**2 / 2, nan)" \
  --reference-label "free fall until impact" \
  --title "block_drop: height of the block's centre" \
  --out "$gallery/${name}_history.png"

name=vertex_vertex_1
run_scene $name
frames $name --times 0,0.3,0.6 --names start,middle,end --out "$gallery/$name"
name=vertex_vertex_2
run_scene $name
frames $name --times 0,0.3,0.6 --names start,middle,end --out "$gallery/$name"

for name in brick_wall jointed_grid; do
  run_scene $name
  frames $name --times 1 --names end --field stress_yy --out "$gallery/$name"
  frames $name --times 1 --names end_displacement --field displacement \
    --out "$gallery/$name"
done

name=default
run_scene $name
# Frames every 20 ms: just after the 10 ms tip pulse, the beam's swing
# at half time (the spinner at the top of its flight), the end.
frames $name --times 0,0.02,0.5,1 --names start,after_pulse,middle,end --initial-cracks \
  --out "$gallery/$name"
history $name \
  --column "point 0 u_y" --column "point 2 u_y" \
  --out "$gallery/${name}_history.png"

# Kirsch's hole, cells against accuracy: the data come from the test
# suite's kirsch_hole (part 3), which ./ndda.sh validate has just run.
kirsch_data="$(dirname "$ndda")/tests/kirsch_hole/cells_against_error.txt"
if [ -f "$kirsch_data" ]; then
  "$py" "$here/scripts/plot_cells_against_error.py" "$kirsch_data" \
    --out "$gallery/kirsch_cells_against_error.png"
fi

# ------------------------------------------------------- the long sweeps
if [ "${NDDA_PICTURES_ONLY_GALLERY:-0}" = 1 ]; then
  echo "validate_pictures: NDDA_PICTURES_ONLY_GALLERY=1: no speed-accuracy or stability sweep"
  exit 0
fi
if [ -f "$here/scripts/speed_accuracy.py" ]; then
  "$py" "$here/scripts/speed_accuracy.py" --ndda "$ndda" --prm-dir "$here/prm" \
    --out-dir "$here/doc/speed_accuracy" \
    --markdown "$here/doc/speed_accuracy/speed_accuracy.md"
fi
if [ -f "$here/scripts/integrator_charts.py" ]; then
  "$py" "$here/scripts/integrator_charts.py" --ndda "$ndda" --prm-dir "$here/prm" \
    --out-dir "$here/doc/integrators" \
    --markdown "$here/doc/integrators/integrators.md"
fi
if [ -f "$here/scripts/stability_map.py" ]; then
  "$py" "$here/scripts/stability_map.py" --ndda "$ndda" --prm-dir "$here/prm" \
    --out-dir "$here/doc/stability" \
    --markdown "$here/doc/stability/stability.md"
fi

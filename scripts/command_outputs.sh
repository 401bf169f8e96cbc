#!/usr/bin/env bash
# What a build's commands write, for comparing two builds (a refactoring must not change it): every
# command run on the built-in and real datasets, with the output files it wrote, its stdout and
# stderr with timings masked, and its exit code, in one folder per command. The Python module
# runs a script too.
#   scripts/command_outputs.sh AMRSTREAM PYTHONPATH OUT_DIR
#   diff -r OLD_OUT NEW_OUT      # nothing but what the change meant to change
# The real datasets are read from ../shared/data/real beside the project; without them those
# commands fail alike in both builds.
set -u
bin=$(readlink -f "$1") pypath=$(readlink -f "$2") out=$3
real=$(cd "$(dirname "$0")/.." && pwd)/../shared/data/real
rm -rf "$out"; mkdir -p "$out"; cd "$out"
export AMRSTREAM_VALIDATION=1
mask() {
  sed -E -e 's/\[[0-9.]+ s\]/[T]/g' -e 's/[0-9.]+(e[-+][0-9]+)? particle-steps\/s/R particle-steps\/s/g' \
    -e '/^(time|memory|rounds|cpu tail|samples|read|gathered|joined|ranks|device) /d' \
    -e 's/device setup [0-9.]+ s: upload [0-9.]+ s, structure [0-9.]+ s, kernels [0-9.]+ s/device setup T/' \
    -e 's/\(device setup [0-9.]+ s before it\)/(device setup T before it)/' \
    -e 's/ built in [0-9.]+ s//' -e 's/\[setup [0-9.]+ s\]/[setup T]/' -e 's/^Usage: [^ ]+ /Usage: amrstream /' -e 's/\r//g' -e '/%/d'
}
n=0
run() {  # run NAME ARGS...: the CLI with ARGS in the folder NAME
  local name=$1; shift
  mkdir -p "$name"
  (cd "$name" && "$bin" "$@" > stdout.raw 2> stderr.raw; echo $? > rc)
  mask < "$name/stdout.raw" > "$name/stdout"; mask < "$name/stderr.raw" > "$name/stderr"
  rm "$name/stdout.raw" "$name/stderr.raw"
  n=$((n + 1))
}
mpi() {  # mpi NAME NP ARGS...
  local name=$1 np=$2; shift 2
  mkdir -p "$name"
  (cd "$name" && mpirun --allow-run-as-root --oversubscribe --bind-to none -np "$np" "$bin" "$@" \
     > stdout.raw 2> stderr.raw; echo $? > rc)
  mask < "$name/stdout.raw" > "$name/stdout"; mask < "$name/stderr.raw" | grep -v -i 'mpi\|prte\|^ *$\|---' > "$name/stderr"
  rm "$name/stdout.raw" "$name/stderr.raw"
}
enzo=$real/enzo-moving7/DD0010/moving7_0010
amrex=$real/amrex-pelelmex-3d/example_plt_3d
flash=$(ls $real/flash-2d-nanowire/* | grep -v -i readme | head -1)
gerris=$(ls $real/gerris-ring/*.txt 2>/dev/null | head -1)

for d in builtin:cloud builtin:abc "$enzo" "$amrex" "$flash" "$gerris"; do
  run "info_$(basename "$d" | tr ':' '_')" info "$d"
done
run gen_cloud gen cloud --levels 3 --root-blocks 2 --target-cells 20000 --out c
run gen_swirl gen swirl --levels 3 --root-blocks 2 --target-cells 20000 --series 3 --interval 0.05 --out sw
run gen_nest gen nest --levels 4 --out n
run convert_enzo convert "$enzo" e.exa
run resample_cloud resample builtin:cloud --dims 24 --out r.vti
run resample_enzo resample "$enzo" --dims 16 --out r.vti

c="--backend cpu"
run t_default trace builtin:cloud --count 32 --steps 300 $c
run t_endpoints trace builtin:cloud --count 32 --steps 300 --endpoints-only $c
run t_vort trace builtin:cloud --count 16 --steps 200 --vorticity --point-data all --compression none $c
run t_rk45 trace builtin:cloud --count 16 --steps 200 --integrator rk45 --tolerance 1e-5 $c
run t_rk2 trace builtin:abc --count 16 --steps 100 --integrator rk2 --direction forward $c
run t_euler trace builtin:abc --count 16 --steps 100 --integrator euler --direction backward --step-mode cell $c
run t_time trace builtin:abc --count 16 --steps 100 --step-mode time --max-time 0.5 $c
run t_limits trace builtin:cloud --count 16 --steps 500 --max-length 0.1 --terminal-speed 1e-3 $c
run t_density trace builtin:cloud --count 16 --steps 100 --seed-density dens --seed-percentile 95 --seeds-out s.txt $c
run t_weighted trace builtin:cloud --count 16 --steps 100 --seed-density dens --seed-weighted $c
run t_grid trace builtin:cloud --seed-grid 3,3,2 --steps 100 --compression lz4 $c
run t_line trace builtin:cloud --seed-line 0.1,0.1,0.1,0.9,0.9,0.9 --count 8 --steps 100 $c
run t_box trace builtin:abc --seed-box 0.2,0.2,0.2,0.4,0.4,0.4 --count 8 --steps 100 --seed 7 $c
run t_linear trace builtin:cloud --count 16 --steps 100 --interpolant linear $c
run t_enzo trace "$enzo" --count 16 --steps 300 $c
run t_enzo_unwrapped trace "$enzo" --count 16 --steps 300 --periodic-lines unwrapped $c
run t_enzo_noper trace "$enzo" --count 16 --steps 300 --periodic none --point-data Density $c
run t_amrex trace "$amrex" --count 16 --steps 200 --point-data none $c
run t_gerris trace "$gerris" --count 16 --steps 200 $c
run t_pieces trace builtin:cloud --count 16 --steps 100 --pieces --out p.pvtp $c
for b in compute rayquery pipeline; do
  run "t_gpu_$b" trace builtin:cloud --count 16 --steps 200 --backend $b
  run "t_gpu_${b}_ep" trace builtin:abc --count 8 --steps 200 --backend $b --endpoints-only --trace-store host
done
run t_gpu_device trace builtin:cloud --count 16 --steps 200 --backend compute --trace-store device --vorticity
run t_gpu_tail trace builtin:abc --count 4 --steps 2000 --backend compute --endpoints-only --cpu-tail 4
run t_seeds_file trace builtin:cloud --seeds ../t_density/s.txt --steps 50 $c

run p_paths pathlines '../gen_swirl/sw_*.exa' --seed-grid 3,3,2 $c
run p_streaks pathlines '../gen_swirl/sw_*.exa' --count 8 --release-every 0.02 $c
run p_gpu pathlines '../gen_swirl/sw_*.exa' --count 8 --backend compute

run r_trace render builtin:cloud --count 16 --steps 100 --width 64 --height 48 --frames 2 --backend compute --axes --scale-bar
run r_file render builtin:cloud --traces ../t_default/traces.vtp --width 64 --height 48 --frames 1 --backend compute --volume dens --colour-by dens --colour-scale log
run r_view render "$enzo" --count 8 --steps 100 --width 64 --height 48 --frames 1 --backend compute --view iso --background white

mpi m_seeds 2 trace builtin:cloud --count 16 --steps 100 $c
mpi m_seeds_gpu 2 trace builtin:cloud --count 16 --steps 100 --backend compute
mpi m_data 2 trace builtin:cloud --count 16 --steps 100 --distribute data $c
mpi m_data_enzo 2 trace "$enzo" --count 16 --steps 100 --distribute data $c
mpi m_rebalance 2 trace builtin:cloud --count 16 --steps 100 --rebalance-steps 20 $c
mpi m_pieces 2 trace builtin:cloud --count 16 --steps 100 --pieces --out p.pvtp $c
mpi m_data_pieces 2 trace builtin:cloud --count 16 --steps 100 --distribute data --pieces --out p.pvtp $c
mpi m_density 2 trace builtin:cloud --count 16 --steps 100 --distribute data --seed-density dens $c

# Errors: the message and the exit code.
run e_vector trace builtin:cloud --vector a,b,c $c
run e_step trace builtin:cloud --step-size 0 $c
run e_periodic trace builtin:cloud --periodic q $c
run e_missing trace /nonexistent.exa $c
run e_seedbox trace builtin:cloud --seed-box 5,5,5,6,6,6 $c
run e_pointdata trace builtin:cloud --point-data nope $c
run e_out_is_in trace "$enzo" --out "$enzo" $c
run e_render_cpu render builtin:cloud --backend cpu
run e_camera render builtin:cloud --camera 35 --backend compute
run e_colour render builtin:cloud --colour-by nope --backend compute --count 4 --steps 10
run e_gen gen nest --root-blocks 3 --out x
run e_minstep trace builtin:cloud --min-step 1 $c
run e_paths_one pathlines ../gen_cloud/c.exa $c
run version --version
run help_trace trace --help

# Python
mkdir -p py
PYTHONPATH=$pypath /usr/bin/python3 - > py/stdout 2> py/stderr <<'PY'
import numpy as np, amrstream, os
os.chdir("py")
ds = amrstream.load("builtin:cloud")
print(ds)
seeds = amrstream.seeds_line((0.1, 0.1, 0.1), (0.9, 0.9, 0.9), 8)
lines = amrstream.trace(ds, seeds, steps=200, backend="cpu")
print(len(lines), lines.points.shape, sorted(lines.point_data.keys()))
np.save("points.npy", lines.points)
lines.to_vtp("lines.vtp")
f = amrstream.prepare(ds, point_data="none")
print(f)
lf = amrstream.trace(f, amrstream.seeds_random(f, 8), steps=50, backend="cpu")
lf.to_vtp("field.vtp")
print(repr(lf))
sw = sorted(__import__("glob").glob("../gen_swirl/sw_*.exa"))
pl = amrstream.pathlines(sw, amrstream.seeds_grid(ds, (2,2,2)), backend="cpu")
pl.to_vtp("paths.vtp")
l2 = amrstream.trace(ds, seeds, steps=100, backend="compute", direction="forward")
l2.to_vtp("gpu.vtp")
img = l2.render(width=64, height=48, frames=1, backend="compute")
np.save("image.npy", img)
d = amrstream.seeds_densest(ds, "dens", 16)
l3 = amrstream.trace(ds, d, steps=50, backend="cpu", step_mode="cell", integrator="rk45")
l3.to_vtp("dense.vtp")
for bad in [dict(interpolant="cubic"), dict(vector="a,b,c"), dict(direction="up"), dict(steps=-1), dict(step_size=0.0), dict(step_mode="nope"), dict(backend="nope")]:
    try:
        amrstream.trace(ds, seeds, **bad)
    except Exception as e:
        print(type(e).__name__, e)
PY
echo $? > py/rc
echo "ran $n commands into $out"

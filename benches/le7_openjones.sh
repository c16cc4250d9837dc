#!/usr/bin/env bash
# rollbench against OpenJones (S. Sudhof 2015, GPL-3 MATLAB, github.com/Rikki-Tikki-Tavi-12/OpenJones)
# on its own LE-7 turbopump example (its README): D 7.938 mm, d_m 38.5 mm, α₀ 20°,
# r_i 0.56·D, r_o 0.52·D, Z 10, 7750.37 kg/m³, E 1.99948e11 Pa, ν 0.25, F_a 2 670 N,
# 50 000 rpm, outer race control. Issue 29, "Validation".
#
# OpenJones is *called* from a copy the user fetched (never part of this repository:
# GPL); this script only reads its solution vector. Its printed Q, σ and speeds are
# wrong whenever f_i ≠ f_o (addSigmaMaxAlpha passes (f_o, f_i) to trigSincosd, declared
# (f_i, f_o)), so the angles and loads are recomputed here from the solution vector with
# its own methods in the right order.
#
# Two runs: "off" (OpenJones's λ_o set to 0 in the temporary copy: no gyroscopic
# friction; rollbench with the friction cap µ_max = 0, the Rust test's reading) and
# "full" (OpenJones as published, λ_o = 2, λ_i = 0; rollbench with
# kinematics.friction_split = "controlling-race").
#
# Usage: benches/le7_openjones.sh PATH/TO/OpenJones/BallBearing.m
# Needs octave (with fsolve, any 7.x); prints OpenJones's ball-0 α_i, α_o, Q_i, Q_o and δ_a.
set -euo pipefail
src=${1:?usage: $0 PATH/TO/OpenJones/BallBearing.m}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for mode in off full; do
  mkdir -p "$tmp/$mode"
  cp "$src" "$tmp/$mode/BallBearing.m"
  if [ "$mode" = off ]; then
    # outer race control: lambda_i = 0, lambda_o = 2 -> 0 (no friction at either race)
    sed -i 's/lambda_o=2;/lambda_o=0;/' "$tmp/$mode/BallBearing.m"
    grep -q 'lambda_o=0;' "$tmp/$mode/BallBearing.m"
  fi
  cat > "$tmp/$mode/run_le7.m" <<'OCT'
D = 7.938e-3;
b = BallBearing();
b.setGeometry(D, 38.5e-3, 20, D*0.56, D*0.52, 10, 0, 0);
b.setPhysical(7750.37, 1.99948e11, 1.99948e11, 0.25, 0.25);
% Octave: the tolerances of optimoptions are set through optimset.
opts = optimset('TolFun', 1e-14, 'TolX', 1e-16, 'MaxIter', 4000, 'MaxFunEvals', 1e6);
geo = b.geometry; phys = b.physical;
ld = BallBearing.makeLoad([2670, 0, 0, 0, 0, 50000]);
f = @(v) b.solvStitcher(geo, phys, ld, 'outer', v);
[v, fval, flag] = fsolve(f, BallBearing.solvInit(geo.z), opts);
s = BallBearing.genSolvStruct(v, geo);
A1 = BallBearing.raceCenterDistAx(s.delta_a, geo, ld);
A2 = BallBearing.raceCenterDistRad(s.delta_ry, s.delta_rz, geo);
[ci, co, si, so] = b.trigSincosd(A1, A2, s.X_1, s.X_2, s.delta_i, s.delta_o, D, geo.f_i, geo.f_o);
[Qi] = b.calcStress(s.delta_i, BallBearing.curvInner(ci, geo.f_i, D, geo.d_m), phys);
[Qo] = b.calcStress(s.delta_o, BallBearing.curvOuter(co, geo.f_o, D, geo.d_m), phys);
printf('exitflag=%d residual=%.3e\n', flag, max(abs(fval)));
printf('alpha_i_deg=%.6f alpha_o_deg=%.6f Q_i_N=%.6f Q_o_N=%.6f delta_a_m=%.9e\n', ...
  atan2d(si(1), ci(1)), atan2d(so(1), co(1)), Qi(1), Qo(1), s.delta_a);
OCT
  echo "== OpenJones, gyroscopic friction $mode"
  (cd "$tmp/$mode" && octave --no-gui --quiet --eval run_le7 2>&1 | grep -E 'exitflag|alpha_i' )
done

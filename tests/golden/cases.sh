# The golden cases: every bundled example in every format the CLI writes, recorded under
# tests/golden/expected/ so that a refactoring that changes a byte of output fails a test.
# Sourced by tools/update_golden.sh (which rewrites the expected files) and by
# tests/golden/CMakeLists.txt (one ctest a case). One case a line: NAME ARGS...; the command runs
# from the repository's top level with `-o FILE` appended, or with @OUT@ in ARGS replaced by FILE
# (for a second output such as --spectra; stdout is then discarded). NAME's extension is the
# format's. Paths are relative so that no output depends on where the repository is.
golden_cases() {
  local v s f
  for v in data/vehicles/*.toml; do
    v=${v#data/vehicles/}; v=${v%.toml}
    for f in table csv json; do
      echo "modes/$v.$f modes data/vehicles/$v.toml --format $f"
      echo "modes/$v.damped.$f modes data/vehicles/$v.toml --damped --format $f"
    done
    echo "modes/$v.vertical.csv modes data/vehicles/$v.toml --dofs vertical --format csv"
    echo "modes/$v.lateral.csv modes data/vehicles/$v.toml --dofs lateral --format csv"
  done
  local m
  for m in resort_car_vertical spring_chain; do
    for f in table csv json; do
      echo "modes/$m.mtx.$f modes --mass data/matrices/${m}_M.mtx --stiffness data/matrices/${m}_K.mtx --format $f"
    done
  done
  echo "modes/spring_chain.mtx.damped.table modes --mass data/matrices/spring_chain_M.mtx --stiffness data/matrices/spring_chain_K.mtx --damping data/matrices/spring_chain_M.mtx --damped"
  for s in data/scenes/*.toml; do
    local name=${s#data/scenes/}; name=${name%.toml}
    if grep -q '^\[simulation\]' "$s"; then
      for f in csv json; do echo "simulate/$name.$f simulate $s --format $f"; done
      echo "simulate/$name.spectra.csv simulate $s --spectra @OUT@ -o -"
      for f in table csv json html; do echo "fft-check/$name.$f fft-check $s --format $f"; done
    elif grep -q '^\[nonlinear_hunting[].]' "$s"; then
      # The nonlinear critical speed (issue 20 item 5), in every format.
      for f in table csv json markdown html; do
        local ext=$f; [ "$f" = markdown ] && ext=md
        echo "hunting/$name.$ext hunting $s --format $f"
      done
    elif grep -q '^\[ride[].]' "$s"; then
      # Ride on random track (issue 21), in every format.
      for f in table csv json markdown html; do
        local ext=$f; [ "$f" = markdown ] && ext=md
        echo "ride/$name.$ext ride $s --format $f"
      done
      # The RMS and weighted RMS alone (--rms-only), in every format, on the smallest ride scene.
      if [ "$name" = two_axle_wagon_fra_class4 ]; then
        for f in table csv json markdown html; do
          local ext=$f; [ "$f" = markdown ] && ext=md
          echo "ride/$name.rms_only.$ext ride $s --rms-only --format $f"
        done
      fi
    else
      for f in markdown html csv json; do
        local ext=$f; [ "$f" = markdown ] && ext=md
        echo "critical-speed/$name.$ext critical-speed $s --format $f -q"
      done
    fi
  done
  for s in data/studies/*.toml; do
    local name=${s#data/studies/}; name=${name%.toml}
    for f in table csv json markdown html; do
      local ext=$f; [ "$f" = markdown ] && ext=md
      echo "compare/$name.$ext compare $s --format $f --threads 2 -q"
    done
    echo "compare/$name.shard1of2.json compare $s --shard 1/2 --threads 2 -q"
  done
  # Hunting stability (issue 20) of the bundled vehicles with wheelsets, in every format, alone and
  # with the design curve and a damping threshold (the CSV holds the root locus only, so its
  # .conicity twin shows that the curve leaves the locus as it is).
  for v in wheelset_on_springs manchester_benchmark_coach_wheelsets; do
    [ -f "data/vehicles/$v.toml" ] || continue
    for f in table csv json markdown html; do
      local ext=$f; [ "$f" = markdown ] && ext=md
      echo "stability/$v.$ext stability data/vehicles/$v.toml --format $f --threads 2"
      echo "stability/$v.conicity.$ext stability data/vehicles/$v.toml --conicity 0.05,0.1,0.2,0.3,0.4 --threshold 5% --format $f --threads 2"
    done
  done
  # The driving gear (issue 22): the bundled locomotives in every format, with no overbalance and
  # with the coupled wheels overbalanced up to alpha = 0.3 (Zhdanov eq. (89a)).
  for v in data/locomotives/*.toml; do
    v=${v#data/locomotives/}; v=${v%.toml}
    for f in table csv json markdown html; do
      local ext=$f; [ "$f" = markdown ] && ext=md
      echo "balance/$v.$ext balance data/locomotives/$v.toml --format $f"
      echo "balance/$v.alpha.$ext balance data/locomotives/$v.toml --alpha 0.3 --format $f"
    done
  done
  # The deprecated spelling of critical-speed (issue 17 item 10) writes the same bytes as the new:
  # this file equals two_axle_freight_wagon_joints.csv.
  echo "critical-speed/two_axle_freight_wagon_joints.old_spelling.csv critical-speed data/vehicles/two_axle_freight_wagon.toml --scene data/scenes/two_axle_freight_wagon_joints.toml --format csv -q"
}

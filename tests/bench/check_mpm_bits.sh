#!/bin/sh
# Bit-identity check of the explicit MPM step (not a ctest: minutes of CPU).
#
#   tests/bench/check_mpm_bits.sh REF_TEPHRA NEW_TEPHRA [WORKDIR] [STEPS]
#
# Runs ../shared/decks/bench/spheres.ups changed so that the spheres collide
# within the first steps (centres at x = -+16.5 mm, gap 3 mm, -+10 m/s), saving
# p.x, p.velocity, p.stress, p.deformationMeasure, p.volume, KineticEnergy and
# StrainEnergy at step 0 and step STEPS (default 60), with GIMP and with linear:
# REF with 1 thread, NEW with 1 and with 2 threads. Passes when, for each
# interpolator and thread count, `tephra extract DIR --var LABEL --step last`
# of NEW prints exactly the text of REF (17 significant digits) for every
# saved particle label, and KineticEnergy.dat / StrainEnergy.dat are
# byte-equal. Prints one line per comparison and "ALL EQUAL" or "DIFFERENT".
# Exit 0 when all equal, 1 otherwise.
set -u
REF=$1
NEW=$2
WORK=${3:-/tmp/check_mpm_bits}
STEPS=${4:-60}
HERE=$(cd "$(dirname "$0")" && pwd)
DECK=$HERE/../../../shared/decks/bench/spheres.ups
[ -f "$DECK" ] || DECK=$(cd "$HERE/../.." && pwd)/../shared/decks/bench/spheres.ups
mkdir -p "$WORK"
status=0
for interp in gimp linear; do
  d=$WORK/spheres_$interp.ups
  sed -e "s|<interpolator>gimp</interpolator>|<interpolator>$interp</interpolator>|" \
      -e 's|<origin>\[-0.03, 0.0, 0.0\]</origin>|<origin>[-0.0165, 0.0, 0.0]</origin>|' \
      -e 's|<origin>\[0.03, 0.0, 0.0\]</origin>|<origin>[0.0165, 0.0, 0.0]</origin>|' \
      -e 's|<velocity>\[2.5, 0.0, 0.0\]</velocity>|<velocity>[10.0, 0.0, 0.0]</velocity>|' \
      -e 's|<velocity>\[-2.5, 0.0, 0.0\]</velocity>|<velocity>[-10.0, 0.0, 0.0]</velocity>|' \
      -e "s|<outputInterval>0.0005</outputInterval>|<outputTimestepInterval>$STEPS</outputTimestepInterval>|" \
      -e 's|<save label="StrainEnergy"/>|<save label="StrainEnergy"/><save label="p.x"/><save label="p.velocity"/><save label="p.stress"/><save label="p.deformationMeasure"/><save label="p.volume"/>|' \
      "$DECK" > "$d"
  grep -q "0.0165" "$d" && grep -q "p.volume" "$d" && grep -q "outputTimestepInterval" "$d" || { echo "deck rewrite failed: $d"; exit 1; }
  "$REF" "$d" --output "$WORK/ref_$interp" --max-steps "$STEPS" --threads 1 --quiet > "$WORK/ref_$interp.log" 2>&1 \
    || { echo "reference run failed ($interp)"; exit 1; }
  for th in 1 2; do
    out=$WORK/new_${interp}_$th
    "$NEW" "$d" --output "$out" --max-steps "$STEPS" --threads $th --quiet > "$out.log" 2>&1 \
      || { echo "new run failed ($interp, $th threads)"; exit 1; }
    for label in p.x p.velocity p.stress p.deformationMeasure p.volume; do
      "$REF" extract "$WORK/ref_$interp" --var $label --step last > "$WORK/a.txt" 2>&1
      "$REF" extract "$out" --var $label --step last > "$WORK/b.txt" 2>&1
      lines=$(wc -l < "$WORK/a.txt")
      if [ "$lines" -gt 1000 ] && cmp -s "$WORK/a.txt" "$WORK/b.txt"; then
        echo "$interp $th threads $label: equal ($lines lines, md5 $(md5sum < "$WORK/a.txt" | cut -c1-12))"
      else
        echo "$interp $th threads $label: DIFFERENT (or too short: $lines lines)"; status=1
      fi
    done
    for dat in KineticEnergy.dat StrainEnergy.dat; do
      a=$(find "$WORK/ref_$interp" -name $dat | head -1)
      b=$(find "$out" -name $dat | head -1)
      if [ -n "$a" ] && [ -n "$b" ] && [ "$(wc -l < "$a")" -ge 2 ] && cmp -s "$a" "$b"; then
        echo "$interp $th threads $dat: byte-equal ($(wc -l < "$a") rows, last: $(tail -1 "$a"))"
      else
        echo "$interp $th threads $dat: DIFFERENT (or no row after step 0)"; status=1
      fi
    done
  done
done
[ $status -eq 0 ] && echo "ALL EQUAL" || echo "DIFFERENT"
exit $status

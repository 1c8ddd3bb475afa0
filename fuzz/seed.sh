#!/usr/bin/env bash
# Seeds the fuzz corpora (fuzz/corpus/<target>/) from the bundled presets, the
# preset fixtures and files the CLI writes. Re-running adds nothing twice.
set -euo pipefail
cd "$(dirname "$0")/.."
corpus=fuzz/corpus
mkdir -p "$corpus"/{preset,link,target_csv,bvh,terrain}

# preset: every bundled preset and every bad-preset fixture.
cp presets/*.json crates/core/tests/fixtures/*.json "$corpus/preset/"

# link: mode byte 2 + JSON deflated into #p= by the target (bare presets and
# full-state envelopes); mode byte 1 + a ?query.
for f in presets/*.json; do
  name=$(basename "$f" .json)
  { printf '\002'; cat "$f"; } > "$corpus/link/bare-$name"
  { printf '\002{"gaitlab_link":1,"preset":'; cat "$f";
    printf ',"state":{"mode":"run","method":"dls","lambda":0.2,"paused":true,"camera":{"yaw_deg":10,"pitch_deg":20,"distance_m":3,"target_m":[0,1,0]}}}'; } \
    > "$corpus/link/full-$name"
  printf '\001?preset=%s&mode=walk&method=sdls' "$name" > "$corpus/link/query-$name"
done
printf '\002{"gaitlab_link":1,"preset":"human","state":{"compare":{"views":["pinv","dls","sdls","ccd"],"scenario":"singularity"}}}' \
  > "$corpus/link/compare"

# target_csv: count byte (effectors − 1) + CSV.
printf '\000t,x,y,z\n0,0,1,0\n0.5,0.1,1,0\n1,0.2,1.1,0\n' > "$corpus/target_csv/one"
printf '\001\xef\xbb\xbft,x0,y0,z0,x1,y1,z1\r\n0,0,1,0,1,1,0\r\n0.1,0,1,0.1,1,1,0.1\r\n' > "$corpus/target_csv/two-bom-crlf"

# terrain: one of each kind, with and without its defaults.
printf '{"kind":"flat"}' > "$corpus/terrain/flat"
printf '{"kind":"plane","slope_deg":10,"direction_deg":90}' > "$corpus/terrain/plane"
printf '{"kind":"stairs","rise_m":0.05,"run_m":0.3,"count":20,"direction_deg":90,"start_m":0.4}' > "$corpus/terrain/stairs"
printf '{"kind":"stairs","rise_m":-0.05,"run_m":0.25,"count":6}' > "$corpus/terrain/stairs-down"
printf '{"kind":"height_field","cell_m":0.25,"cols":3,"rows":2,"heights_m":[0,0.1,0.2,0.05,0.15,0],"friction":[0.5,0.8]}' > "$corpus/terrain/field"
printf '{"kind":"height_field","cell_m":0.1,"cols":2,"rows":2,"origin_m":[-1,2],"heights_m":[0.3,0.3,0.3,0.3]}' > "$corpus/terrain/field-level"
printf '{"kind":"rough","seed":7,"difficulty":0.5}' > "$corpus/terrain/rough"
printf '{"kind":"rough","seed":1,"difficulty":1,"max_height_m":0.2,"feature_m":0.1,"cell_m":0.2,"size_m":[4,4],"origin_m":[0,0]}' > "$corpus/terrain/rough-small"

# bvh: a short take of each engine, written by the CLI.
cli=(cargo run -q --release -p gaitlab-cli --)
for p in human poda-quadruped raibert-biped; do
  "${cli[@]}" run "$p" --seconds 0.1 --bvh "$corpus/bvh/$p.bvh" > /dev/null
done
echo "seeded: $(for t in preset link target_csv bvh terrain; do printf '%s %s  ' "$t" "$(ls "$corpus/$t" | wc -l)"; done)"

#!/bin/sh
# Launcher mode under a real mpirun (Open MPI): the coordinator waits at a rendezvous,
# `mpirun -n 4 povwall worker --rendezvous ...` starts the workers, which take their rank
# and size from Open MPI's environment. The image must equal the one-process render and
# mpirun must end cleanly (every rank served its one job and exited 0).
# Without Open MPI's mpirun: exits 77 (skipped) with a message.
set -u
POVWALL=$1
SCENE=$2
if ! command -v mpirun >/dev/null || ! mpirun --version 2>/dev/null | grep -q "Open MPI"; then
    echo "skipped: needs Open MPI's mpirun (Debian: openmpi-bin)"; exit 77
fi
DIR=$(mktemp -d)
trap 'kill $COORD 2>/dev/null; rm -rf "$DIR"' EXIT
"$POVWALL" render "$SCENE" -W 64 -H 48 -q -o "$DIR/one.exr" || exit 1
# Port 0: the coordinator picks one and says where it waits.
"$POVWALL" render "$SCENE" -W 64 -H 48 -o "$DIR/launched.exr" --boxes 2x2x2 \
    --token mpijob --rendezvous 127.0.0.1:0 --rendezvous-timeout 60 2>"$DIR/err" &
COORD=$!
AT=""
for _ in $(seq 100); do
    AT=$(sed -n 's/^povwall: rendezvous on \([0-9.:]*\), waiting.*/\1/p' "$DIR/err")
    [ -n "$AT" ] && break
    sleep 0.1
done
[ -n "$AT" ] || { echo "the coordinator did not say its rendezvous"; cat "$DIR/err"; exit 1; }
mpirun --allow-run-as-root --oversubscribe -n 4 \
    "$POVWALL" worker --rendezvous "$AT" --token mpijob --threads 1 >"$DIR/mpi" 2>&1
MPI=$?
wait $COORD
RC=$?
cat "$DIR/err"
[ $MPI -eq 0 ] || { echo "mpirun ended with $MPI"; cat "$DIR/mpi"; exit 1; }
[ $RC -eq 0 ] || { echo "the coordinator ended with $RC"; exit 1; }
[ "$(grep -c 'listening on' "$DIR/mpi")" -eq 4 ] || { echo "not 4 workers"; cat "$DIR/mpi"; exit 1; }
"$POVWALL" diff "$DIR/one.exr" "$DIR/launched.exr" --max-rmse 1e-6 || exit 1
echo "mpirun -n 4: the image equals the one-process render"

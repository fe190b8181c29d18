#!/bin/sh
# Four "hosts" as network namespaces joined by veth pairs to a bridge; one povwall worker in
# each, the coordinator in the root namespace. The image must equal the one-process render.
# Needs root with CAP_NET_ADMIN; otherwise exits 77 (skipped) with a message.
set -u
POVWALL=$1
SCENE=$2
if [ "$(id -u)" != 0 ] || ! command -v ip >/dev/null; then
    echo "skipped: needs root and iproute2 (ip netns)"; exit 77
fi
TAG=pw$$
BR=br$TAG
DIR=$(mktemp -d)
cleanup() {
    for i in 1 2 3 4; do
        [ -f "$DIR/pid$i" ] && kill "$(cat "$DIR/pid$i")" 2>/dev/null
        ip netns del "$TAG$i" 2>/dev/null
        ip link del "v$TAG$i" 2>/dev/null
    done
    ip link del "$BR" 2>/dev/null
    rm -rf "$DIR"
}
trap cleanup EXIT
if ! ip link add "$BR" type bridge 2>/dev/null; then
    echo "skipped: cannot create network devices (no CAP_NET_ADMIN)"; exit 77
fi
ip addr add 10.213.7.1/24 dev "$BR" && ip link set "$BR" up || exit 1
WORKERS=""
for i in 1 2 3 4; do
    ns=$TAG$i
    ip netns add "$ns" || exit 1
    ip link add "v$TAG$i" type veth peer name eth0 netns "$ns" || exit 1
    ip link set "v$TAG$i" master "$BR" up || exit 1
    ip -n "$ns" addr add "10.213.7.1$i/24" dev eth0 || exit 1
    ip -n "$ns" link set eth0 up && ip -n "$ns" link set lo up || exit 1
    ip netns exec "$ns" "$POVWALL" worker --listen "10.213.7.1$i:7400" --token nsjob \
        --threads 1 >"$DIR/w$i.log" 2>&1 &
    echo $! >"$DIR/pid$i"
    WORKERS="$WORKERS${WORKERS:+,}10.213.7.1$i:7400"
done
for i in 1 2 3 4; do  # wait for each worker to listen
    n=0; until grep -q listening "$DIR/w$i.log" 2>/dev/null; do
        n=$((n + 1)); [ $n -gt 100 ] && { echo "worker $i did not start"; cat "$DIR/w$i.log"; exit 1; }
        sleep 0.05
    done
done
"$POVWALL" render "$SCENE" -W 48 -H 36 -q -o "$DIR/one.exr" || exit 1
"$POVWALL" render "$SCENE" -W 48 -H 36 -q -o "$DIR/hosts.exr" --boxes 2x2x2 \
    --workers "$WORKERS" --token nsjob || exit 1
"$POVWALL" diff "$DIR/one.exr" "$DIR/hosts.exr" --max-rmse 1e-6 || exit 1
echo "4 namespaces: image identical"

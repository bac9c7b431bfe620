#!/usr/bin/env bash
# Runs a command in a network namespace of its own: loopback, plus a tun device that carries an
# address but leads nowhere (getaddrinfo's AI_ADDRCONFIG, which slurmctld uses to open its
# listening socket, finds no IPv4 address on loopback alone). Nothing can reach the cluster a
# test starts in it, and it can reach nothing. The namespace (and the device) end with the
# command.
set -euo pipefail
exec unshare -n bash -c 'set -e; ip link set lo up; ip tuntap add dev spt0 mode tun; ip addr add 10.254.0.1/32 dev spt0;
                         ip link set spt0 up; exec "$@"' in_netns "$@"

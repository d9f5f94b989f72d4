#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# Runs a command with a private headless X server (Xvfb) for ParaView's
# rendering, then stops the server. Usage: scripts/with-xvfb.sh CMD [ARGS...]
# Debian's ParaView renders through X, even with --force-offscreen-rendering.
# The server picks a free display itself (-displayfd), so several of these
# can start at once. -noreset: without it Xvfb resets when its last client
# disconnects, and ParaView clients that connect meanwhile abort at random
# under load ("bad X server connection").
set -u
if [ -n "${DISPLAY:-}" ] && [ "${NV_FORCE_XVFB:-0}" != "1" ]; then
  exec "$@"
fi
ready="$(mktemp)"
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$ready" >/dev/null 2>&1 &
server=$!
for _ in $(seq 1 200); do
  [ -s "$ready" ] && break
  sleep 0.05
done
display="$(head -n 1 "$ready")"
rm -f "$ready"
if [ -z "$display" ]; then
  echo "with-xvfb: Xvfb did not start" >&2
  kill "$server" 2>/dev/null
  exit 1
fi
export DISPLAY=":$display"
"$@"
status=$?
kill "$server" 2>/dev/null
wait "$server" 2>/dev/null
exit $status

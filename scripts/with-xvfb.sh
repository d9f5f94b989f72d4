#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# Runs a command with a private headless X server (Xvfb) for ParaView's
# rendering, then stops the server. Usage: scripts/with-xvfb.sh CMD [ARGS...]
# Debian's ParaView renders through X, even with --force-offscreen-rendering.
# Each server takes the first free display from :100 on, never :0: a
# ParaView process started without DISPLAY (a test's own subprocess) reaches
# for :0 when a server is there, and another test stopping that server would
# cut it off. Several of these can start at once: a server that loses a
# display to another (it exits) tries the next. -noreset: without it Xvfb
# resets when its last client disconnects, and ParaView clients that connect
# meanwhile abort at random under load ("bad X server connection").
set -u
if [ -n "${DISPLAY:-}" ] && [ "${NV_FORCE_XVFB:-0}" != "1" ]; then
  exec "$@"
fi
display=""
for number in $(seq 100 299); do
  [ -e "/tmp/.X$number-lock" ] && continue
  ready="$(mktemp)"
  # -displayfd: the server writes the display's number there once it is ready.
  Xvfb ":$number" -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$ready" >/dev/null 2>&1 &
  server=$!
  for _ in $(seq 1 200); do
    if [ -s "$ready" ] || ! kill -0 "$server" 2>/dev/null; then
      break
    fi
    sleep 0.05
  done
  display="$(head -n 1 "$ready")"
  rm -f "$ready"
  [ -n "$display" ] && break
  kill "$server" 2>/dev/null # it did not start there: the next display
  wait "$server" 2>/dev/null
done
if [ -z "$display" ]; then
  echo "with-xvfb: Xvfb did not start (displays :100 to :299 tried)" >&2
  exit 1
fi
export DISPLAY=":$display"
"$@"
status=$?
kill "$server" 2>/dev/null
wait "$server" 2>/dev/null
exit $status

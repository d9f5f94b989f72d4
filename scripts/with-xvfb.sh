#!/usr/bin/env bash
# Runs a command with a private headless X server (Xvfb) for ParaView's
# rendering, then stops the server. Usage: scripts/with-xvfb.sh CMD [ARGS...]
# Debian's ParaView renders through X, even with --force-offscreen-rendering.
set -u
if [ -n "${DISPLAY:-}" ] && [ "${NV_FORCE_XVFB:-0}" != "1" ]; then
  exec "$@"
fi
display=""
for n in $(seq 91 140); do
  if [ ! -e "/tmp/.X11-unix/X$n" ] && [ ! -e "/tmp/.X$n-lock" ]; then
    display=$n
    break
  fi
done
[ -n "$display" ] || { echo "with-xvfb: no free display" >&2; exit 1; }
Xvfb ":$display" -screen 0 1280x1024x24 -nolisten tcp >/dev/null 2>&1 &
server=$!
for _ in $(seq 1 100); do
  [ -e "/tmp/.X11-unix/X$display" ] && break
  sleep 0.1
done
export DISPLAY=":$display"
"$@"
status=$?
kill "$server" 2>/dev/null
wait "$server" 2>/dev/null
exit $status

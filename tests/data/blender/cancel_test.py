"""A cancelled render leaves no rtcli process behind; run by tests/tools/test_blender_addon.cpp:

  python3 tests/data/blender/cancel_test.py BLENDER RTCLI OUT

Starts Blender in the background on addon_test.py's "heavy" case, waits until its rtcli process
runs, then sends Blender SIGINT: in the background that is Blender's break (Esc in the UI), which
the engine's test_break() sees. Checks that Blender's render returns, that the rtcli process has
ended and been reaped, and that the engine's temporary folder is gone. Prints "addon cancel: ok".
"""
import os
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def children(pid):
    """(pid, name) of each process whose parent is pid."""
    out = []
    for entry in os.listdir('/proc'):
        if not entry.isdigit():
            continue
        try:
            with open('/proc/%s/stat' % entry) as f:
                stat = f.read()
        except OSError:
            continue
        name = stat[stat.index('(') + 1:stat.rindex(')')]
        parent = int(stat[stat.rindex(')') + 2:].split()[1])
        if parent == pid:
            out.append((int(entry), name))
    return out


def main():
    blender, rtcli, out = sys.argv[1], sys.argv[2], os.path.abspath(sys.argv[3])
    temp = os.path.join(out, 'tmp')
    os.makedirs(temp, exist_ok=True)
    os.makedirs(os.path.join(out, 'config'), exist_ok=True)
    env = dict(os.environ, BLENDER_USER_SCRIPTS=os.path.join(out, 'scripts'), BLENDER_USER_CONFIG=os.path.join(out, 'config'),
               TMPDIR=temp)
    # Blender's Python looks for its packages (numpy) from the python3 first on PATH: not this
    # interpreter's folder, if a virtual environment or pyenv put it there.
    own = os.path.dirname(sys.executable)
    if own not in ('/usr/bin', '/bin'):
        env['PATH'] = os.pathsep.join(p for p in env.get('PATH', '').split(os.pathsep) if p != own)
    log = open(os.path.join(out, 'blender.log'), 'w')
    process = subprocess.Popen([blender, '-b', '--factory-startup', '--python-exit-code', '1', '--python',
                                os.path.join(HERE, 'addon_test.py'), '--', 'heavy', out, rtcli],
                               stdout=log, stderr=subprocess.STDOUT, env=env)
    found = []
    deadline = time.time() + 120
    while not found and time.time() < deadline and process.poll() is None:
        found = [pid for pid, name in children(process.pid) if name == 'rtcli']
        time.sleep(0.1)
    if not found:
        process.kill()
        sys.exit('addon cancel: no rtcli process started under Blender (see %s/blender.log)' % out)
    rendering = found[0]
    time.sleep(1.0)  # well into the render
    sent = time.time()
    process.send_signal(signal.SIGINT)
    try:
        process.wait(timeout=60)
    except subprocess.TimeoutExpired:
        process.kill()
        sys.exit('addon cancel: Blender did not end within 60 s of the break')
    took = time.time() - sent
    log.close()
    text = open(os.path.join(out, 'blender.log')).read()
    still_there = os.path.exists('/proc/%d' % rendering)
    leftovers = os.listdir(temp)
    print('addon cancel: rtcli (pid %d) ran; Blender ended %.2f s after the break; rtcli process left: %s; '
          'temporary files left: %s' % (rendering, took, still_there, leftovers or 'none'))
    if still_there or leftovers or 'addon heavy: the render returned' not in text:
        sys.exit('addon cancel: FAILED\n' + text[-3000:])
    print('addon cancel: ok')


if __name__ == '__main__':
    main()

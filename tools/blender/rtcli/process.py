# Runs rtcli for the render engine: its progress lines ("rtcli: progress 42%", render --progress
# lines) go to a callback as they come, everything else is kept for the report, and the process
# is ended (SIGTERM, then SIGKILL after a grace period) as soon as the caller says stop, so that
# Esc in Blender leaves nothing running. No bpy here: the tests run it with plain callbacks.
#
# Licence: Apache-2.0, as the rest of rtcli.
import queue
import re
import subprocess
import threading

PROGRESS = re.compile(r'^rtcli: progress (\d+)%')


class Outcome:
    def __init__(self, code, lines, cancelled):
        self.code = code            # rtcli's exit status (None if it could not be started)
        self.lines = lines          # what it printed, progress lines left out
        self.cancelled = cancelled  # ended because the caller asked

    def errors(self):
        """rtcli's error messages, each with the indented lines that continue it (located excerpts)."""
        out = []
        for line in self.lines:
            if line.startswith('rtcli: error') or (not out and 'error' in line.lower()):
                out.append(line)
            elif out and line.startswith((' ', '\t')):
                out[-1] += '\n' + line
        return out

    def warnings(self):
        return [line for line in self.lines if line.startswith('rtcli: warning')]


def _read_lines(stream, into):
    for line in stream:
        into.put(line.rstrip('\n'))
    into.put(None)


def run(argv, cwd, on_progress, should_stop, poll_seconds=0.05, grace_seconds=5.0, on_start=None):
    """Runs argv in cwd. on_progress(fraction) for each progress line; should_stop() polled while it
    runs. Returns an Outcome once the process has ended and been reaped."""
    try:
        process = subprocess.Popen(argv, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, text=True, errors='replace', bufsize=1)
    except OSError as e:
        return Outcome(None, ['rtcli: error: could not run %s: %s' % (argv[0], e.strerror or e)], False)
    if on_start:
        on_start(process.pid)
    lines = queue.Queue()
    reader = threading.Thread(target=_read_lines, args=(process.stdout, lines), daemon=True)
    reader.start()
    kept = []
    cancelled = False
    finished = False
    while not finished:
        try:
            line = lines.get(timeout=poll_seconds)
        except queue.Empty:
            line = ''
        if line is None:
            finished = True
        elif line:
            match = PROGRESS.match(line)
            if match:
                on_progress(min(1.0, int(match.group(1)) / 100.0))
            else:
                kept.append(line)
        if not cancelled and should_stop():
            cancelled = True
            process.terminate()  # rtcli stops its render at once and writes nothing (exit 143)
            try:
                process.wait(timeout=grace_seconds)
            except subprocess.TimeoutExpired:
                process.kill()
    code = process.wait()
    reader.join()
    process.stdout.close()
    return Outcome(code, kept, cancelled)

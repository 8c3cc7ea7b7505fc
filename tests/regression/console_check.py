"""Runs a command and checks its console (stdout and stderr together).

usage: console_check.py [--expect REGEX]... [--forbid REGEX]... [--count REGEX N]...
                        [--absent FILE]... [--exists FILE]... [--remove FILE]... -- COMMAND...

Passes when the command exits 0, every --expect regex (Python, MULTILINE)
matches somewhere, no --forbid regex matches, each --count regex matches
exactly N lines, no --absent file exists and every --exists file does after
the run. --remove files are deleted before it. Every check is printed; the
exit code is 0 when all hold, 1 otherwise.
"""
import os
import re
import subprocess
import sys


def main(argv):
    expect, forbid, count, absent, exists, remove = [], [], [], [], [], []
    i = 1
    while i < len(argv) and argv[i] != "--":
        option = argv[i]
        if option == "--count":
            count.append((argv[i + 1], int(argv[i + 2])))
            i += 3
            continue
        {"--expect": expect, "--forbid": forbid, "--absent": absent, "--exists": exists,
         "--remove": remove}[option].append(argv[i + 1])
        i += 2
    command = argv[i + 1:]
    if not command:
        print(__doc__)
        return 2
    for path in remove:
        if os.path.exists(path):
            os.remove(path)
    print("run: %s" % " ".join(command))
    proc = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=600)
    text = proc.stdout
    print(text)
    failures = []

    def check(ok, what):
        print(("ok:     " if ok else "FAILED: ") + what)
        if not ok:
            failures.append(what)

    check(proc.returncode == 0, "exit code 0 (got %d)" % proc.returncode)
    for pattern in expect:
        check(re.search(pattern, text, re.MULTILINE) is not None, "the console matches /%s/" % pattern)
    for pattern in forbid:
        check(re.search(pattern, text, re.MULTILINE) is None, "the console does not match /%s/" % pattern)
    for pattern, n in count:
        found = len(re.findall(pattern, text, re.MULTILINE))
        check(found == n, "%d line(s) match /%s/ (found %d)" % (n, pattern, found))
    for path in absent:
        check(not os.path.exists(path), "%s does not exist" % path)
    for path in exists:
        check(os.path.exists(path), "%s exists" % path)
    print("PASS" if not failures else "%d check(s) failed" % len(failures))
    return 0 if not failures else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))

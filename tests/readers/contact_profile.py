"""The contact profile text file stem.contact1.txt (doc/output-format.md):
one block per frame with a '# frame N  time T  step S' line, then one
line per slave node: s0 x y gap pressure shear status slip lambda_n
lambda_t. The readers' checks compare what they read with it."""


def read_profile(path):
    """List of (time, rows) per frame; rows are lists of floats."""
    frames = []
    with open(path) as f:
        for line in f:
            words = line.split()
            if line.startswith('# frame'):
                frames.append((float(words[4]), []))
            elif words and not line.startswith('#'):
                frames[-1][1].append([float(w) for w in words])
    return frames


def check(ok, what):
    """Print and count a check; raise at the end through `finish`."""
    print(('pass  ' if ok else 'FAIL  ') + what)
    if not ok:
        check.failed += 1


check.failed = 0


def finish():
    if check.failed:
        raise SystemExit(f'{check.failed} check(s) failed')
    print('all checks passed')

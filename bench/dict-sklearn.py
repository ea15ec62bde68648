#!/usr/bin/python3
"""dict-sklearn.py MESH D [N_INIT] -- the peer for dict-learn -l 0: scikit-learn
KMeans (best of N_INIT greedy k-means++ starts, Lloyd, tol 0) on the frames
of a MESH stream (plain or raw).  Prints "energy=E seconds=S" (S: fit only)."""
import sys, time
import numpy as np
from sklearn.cluster import KMeans

def read_mesh(path):
    with open(path, 'rb') as f:
        data = f.read()
    pos = 0
    def line():
        nonlocal pos
        e = data.index(b'\n', pos)
        s = data[pos:e].decode()
        pos = e + 1
        return s
    magic = line().split()
    raw = len(magic) > 2 and magic[2] == 'raw'
    hdr = {}
    while len(hdr) < 3:
        s = line().split()
        if s and not s[0].startswith('#'):
            hdr[s[0]] = s[1]
    nv, nf = int(hdr['vertices']), int(hdr['faces'])
    frames = []
    if raw:
        pos += 12 * nf
        while pos < len(data):
            s = line()
            if not s.startswith('frame'):
                continue
            frames.append(np.frombuffer(data, '<f8', 3 * nv, pos))
            pos += 24 * nv
    else:
        txt = data[pos:].decode().split('\n')
        i = 0
        while i < len(txt):
            if txt[i].startswith('frame'):
                frames.append(np.array(' '.join(txt[i + 1:i + 1 + nv]).split(), float))
                i += nv + 1
            else:
                i += 1
    return np.vstack(frames)

X = read_mesh(sys.argv[1])
d = int(sys.argv[2])
n_init = int(sys.argv[3]) if len(sys.argv) > 3 else 10
t = time.time(); c = time.process_time()
km = KMeans(n_clusters=d, n_init=n_init, random_state=0, tol=0).fit(X)
t = time.time() - t; c = time.process_time() - c
# inertia recomputed in double precision from the labels (sklearn's own is the same)
E = sum(((X[km.labels_ == a] - X[km.labels_ == a].mean(0)) ** 2).sum() for a in range(d) if (km.labels_ == a).any())
print("energy=%.10g seconds=%.3f cpu=%.3f frames=%d dims=%d" % (E, t, c, X.shape[0], X.shape[1]))

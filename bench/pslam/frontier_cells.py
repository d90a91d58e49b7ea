#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Frontier cells of a map_server map (free pixels with an unknown 4-neighbour), N of them
spread by a seeded shuffle, printed as X,Y in metres: targets for `lookahead predict`."""
import random, re, sys

def read_pgm(path):
    data = open(path, 'rb').read()
    tokens, i = [], 0
    while len(tokens) < 4:
        while data[i:i + 1].isspace(): i += 1
        if data[i:i + 1] == b'#':
            while data[i:i + 1] != b'\n': i += 1
            continue
        j = i
        while not data[j:j + 1].isspace(): j += 1
        tokens.append(data[i:j]); i = j
    w, h = int(tokens[1]), int(tokens[2])
    return w, h, data[i + 1:i + 1 + w * h]

def main(yaml_path, count, seed):
    text = open(yaml_path).read()
    image = re.search(r'image:\s*(\S+)', text).group(1)
    res = float(re.search(r'resolution:\s*([-\d.e]+)', text).group(1))
    ox, oy = [float(v) for v in re.search(r'origin:\s*\[([^,]+),([^,]+),', text).groups()]
    w, h, px = read_pgm(yaml_path.rsplit('/', 1)[0] + '/' + image if '/' in yaml_path else image)
    unknown, free = 205, lambda v: v > 215  # map_server greys: 205 unknown, 255 (1 - p)
    cells = []
    for y in range(1, h - 1):
        for x in range(1, w - 1):
            if free(px[y * w + x]) and unknown in (px[y * w + x - 1], px[y * w + x + 1], px[(y - 1) * w + x], px[(y + 1) * w + x]):
                cells.append((ox + (x + 0.5) * res, oy + (h - 1 - y + 0.5) * res))
    random.Random(seed).shuffle(cells)
    for x, y in cells[:count]: print(f"{x:.2f},{y:.2f}")

if __name__ == '__main__':
    main(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 20, int(sys.argv[3]) if len(sys.argv) > 3 else 1)

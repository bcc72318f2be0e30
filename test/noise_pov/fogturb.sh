#!/bin/sh
# Writes fogturb.txt: POV-Ray 3.7's render of fogturb.pov (32x24, no
# anti-aliasing, 16-bit linear PPM), one pixel a line: x y r g b (0 to 65535)
povray -D +W32 +H24 -GA +FP16 File_Gamma=1.0 fogturb.pov +Ofogturb.ppm >/dev/null 2>&1
python3 - <<'PY'
d = open('fogturb.ppm', 'rb').read()
fields, i = [], 0
while len(fields) < 4:
    while d[i:i+1].isspace(): i += 1
    if d[i:i+1] == b'#':
        while d[i:i+1] != b'\n': i += 1
        continue
    j = i
    while not d[j:j+1].isspace(): j += 1
    fields.append(d[i:j]); i = j
i += 1
w, h, m = int(fields[1]), int(fields[2]), int(fields[3])
with open('fogturb.txt', 'w') as f:
    for y in range(h):
        for x in range(w):
            k = i + 6 * (y * w + x)
            r, g, b = (d[k] << 8 | d[k+1]), (d[k+2] << 8 | d[k+3]), (d[k+4] << 8 | d[k+5])
            f.write('%d %d %d %d %d\n' % (x, y, r, g, b))
PY
rm -f fogturb.ppm

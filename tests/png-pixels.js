// png-pixels.js -- pixel counts on PNG screenshots, for the browser tests
// (node, no packages: zlib is built in).  Non-interlaced 8-bit RGB/RGBA only.
//
//   node png-pixels.js bg A.png X0,Y0,X1,Y1 R,G,B
//       fraction of the pixels in the box [X0,X1) x [Y0,Y1) that differ from
//       the colour R,G,B (by more than 8 in some channel)
//   node png-pixels.js diff A.png B.png X0,Y0,X1,Y1
//       fraction of the pixels in the box that differ (same test) between A and B
'use strict';
const fs = require('fs'), zlib = require('zlib');

function readPNG(path) {
  const b = fs.readFileSync(path);
  if (b.readUInt32BE(0) !== 0x89504e47) throw new Error(path + ': not a PNG');
  let p = 8, w, h, depth, type, interlace;
  const idat = [];
  while (p < b.length) {
    const len = b.readUInt32BE(p), kind = b.toString('latin1', p + 4, p + 8), d = b.subarray(p + 8, p + 8 + len);
    if (kind === 'IHDR') { w = d.readUInt32BE(0); h = d.readUInt32BE(4); depth = d[8]; type = d[9]; interlace = d[12]; }
    else if (kind === 'IDAT') idat.push(d);
    else if (kind === 'IEND') break;
    p += 12 + len;
  }
  if (depth !== 8 || (type !== 2 && type !== 6) || interlace)
    throw new Error(`${path}: only 8-bit RGB/RGBA non-interlaced PNG (depth ${depth}, type ${type})`);
  const bpp = type === 6 ? 4 : 3, stride = w * bpp, raw = zlib.inflateSync(Buffer.concat(idat));
  const px = Buffer.alloc(h * stride);
  for (let y = 0; y < h; y++) {
    const f = raw[y * (stride + 1)], src = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    const row = px.subarray(y * stride, (y + 1) * stride), up = y ? px.subarray((y - 1) * stride, y * stride) : null;
    for (let i = 0; i < stride; i++) {
      const a = i >= bpp ? row[i - bpp] : 0, u = up ? up[i] : 0, c = up && i >= bpp ? up[i - bpp] : 0;
      let v = src[i];
      if (f === 1) v += a;
      else if (f === 2) v += u;
      else if (f === 3) v += (a + u) >> 1;
      else if (f === 4) { const q = a + u - c, pa = Math.abs(q - a), pb = Math.abs(q - u), pc = Math.abs(q - c);
        v += pa <= pb && pa <= pc ? a : pb <= pc ? u : c; }
      else if (f !== 0) throw new Error(path + ': bad filter ' + f);
      row[i] = v & 255;
    }
  }
  return { w, h, bpp, px, at: (x, y) => { const o = y * stride + x * bpp; return [px[o], px[o + 1], px[o + 2]]; } };
}
const nums = (s) => s.split(',').map(Number);
const differ = (a, b) => Math.abs(a[0] - b[0]) > 8 || Math.abs(a[1] - b[1]) > 8 || Math.abs(a[2] - b[2]) > 8;
function count(img, box, test) {
  const [x0, y0, x1, y1] = box.map((v, i) => Math.min(v, i % 2 ? img.h : img.w));
  let n = 0, hit = 0;
  for (let y = y0; y < y1; y++) for (let x = x0; x < x1; x++) { n++; if (test(x, y)) hit++; }
  if (!n) throw new Error('empty box');
  return hit / n;
}
const [mode, ...args] = process.argv.slice(2);
if (mode === 'bg') {
  const img = readPNG(args[0]), bg = nums(args[2]);
  console.log(count(img, nums(args[1]), (x, y) => differ(img.at(x, y), bg)).toFixed(6));
} else if (mode === 'diff') {
  const a = readPNG(args[0]), b = readPNG(args[1]);
  if (a.w !== b.w || a.h !== b.h) throw new Error('sizes differ');
  console.log(count(a, nums(args[2]), (x, y) => differ(a.at(x, y), b.at(x, y))).toFixed(6));
} else {
  console.error('usage: node png-pixels.js bg A.png X0,Y0,X1,Y1 R,G,B | diff A.png B.png X0,Y0,X1,Y1');
  process.exit(2);
}

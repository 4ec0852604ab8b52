// What the browser tests share: the real implicitizer-server on a loopback port
// serving clients/web, Debian's chromium (headless, through playwright-core) with
// WebGL2 on SwiftShader, console watching, and a decoder of the PNGs the renderer
// and the screenshots write. Environment: IMPLICITIZER_SERVER (default
// build/bin/implicitizer-server), CHROMIUM (default /usr/bin/chromium),
// IMPLICITIZER_SHARED_DIR (default ../shared).
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import zlib from 'node:zlib';
import { chromium } from 'playwright-core';

const here = path.dirname(fileURLToPath(import.meta.url));
export const root = path.resolve(here, '..', '..');
export const serverPath = path.resolve(process.env.IMPLICITIZER_SERVER || path.join(root, 'build', 'bin', 'implicitizer-server'));
export const chromiumPath = process.env.CHROMIUM || '/usr/bin/chromium';
export const sharedDir = path.resolve(process.env.IMPLICITIZER_SHARED_DIR || path.join(root, '..', 'shared'));

// WebGL2 in headless Chromium without a GPU: ANGLE on SwiftShader. The network of
// this machine is closed: the other flags stop Chromium's own background requests.
// playwright-core gives every launch a fresh temporary profile (--user-data-dir).
export const CHROMIUM_ARGS = [
  '--no-sandbox',
  '--use-gl=angle',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--disable-default-apps',
  '--disable-domain-reliability',
  '--disable-features=Translate,OptimizationHints,MediaRouter,AutofillServerCommunication',
  '--no-first-run',
  '--no-default-browser-check',
  '--disable-quic',
  '--metrics-recording-only',
];

export const BACKGROUND = 242; // the renderer's grey 0.95 as a byte

/// Starts `implicitizer-server --host 127.0.0.1 --port 0 --static clients/web` and
/// resolves to {process, url, logPath} once it prints its address. The access log goes
/// to a temporary file, kept (and named on exit) only when a test failed.
export function startServer() {
  assert.ok(fs.existsSync(serverPath), `no server binary at ${serverPath} (build it first)`);
  const logDir = fs.mkdtempSync(path.join(os.tmpdir(), 'implicitizer-web-'));
  const logPath = path.join(logDir, 'server.log');
  process.on('exit', (code) => {
    if (code === 0 && !process.exitCode) fs.rmSync(logDir, { recursive: true, force: true });
    else console.log(`# server log: ${logPath}`);
  });
  const log = fs.openSync(logPath, 'w');
  // --max-timeout-ms: the tests' reference CPU renders ask for minutes, so that a
  // loaded 2-core machine (SwiftShader shares its cores) never decides a verdict.
  const flags = ['--host', '127.0.0.1', '--port', '0', '--max-timeout-ms', '600000'];
  const child = spawn(serverPath, [...flags, '--static', path.join(root, 'clients', 'web')], {
    stdio: ['ignore', 'pipe', log],
  });
  return new Promise((resolve, reject) => {
    let out = '';
    const timer = setTimeout(() => reject(new Error(`the server did not start within 20 s (log: ${logPath})`)), 20000);
    child.on('error', reject);
    child.on('exit', (code) => reject(new Error(`the server exited with ${code} before listening (log: ${logPath})`)));
    child.stdout.on('data', (chunk) => {
      out += chunk;
      const m = /implicitizer-server listening on (http:\/\/\S+)/.exec(out);
      if (m) {
        clearTimeout(timer);
        child.removeAllListeners('exit');
        child.stdout.resume();
        resolve({ process: child, url: m[1], logPath });
      }
    });
  });
}

/// SIGTERM, then waits (at most 10 s) for the server to exit.
export async function stopServer(server) {
  if (!server) return;
  const exited = new Promise((resolve) => server.process.on('exit', resolve));
  server.process.kill('SIGTERM');
  await Promise.race([exited, new Promise((resolve) => setTimeout(resolve, 10000))]);
}

/// Launches headless chromium with CHROMIUM_ARGS and `extraArgs`.
export function launchChromium(extraArgs = []) {
  assert.ok(fs.existsSync(chromiumPath), `no chromium at ${chromiumPath}`);
  return chromium.launch({ executablePath: chromiumPath, headless: true, args: [...CHROMIUM_ARGS, ...extraArgs], timeout: 60000 });
}

/// Records the page's uncaught exceptions and console errors in `errors` (failed
/// resource loads aside: a test that expects a 4xx answer causes one).
export function watchErrors(page, errors) {
  page.on('pageerror', (e) => errors.push(`pageerror: ${e.message}`));
  page.on('console', (m) => {
    if (m.type() === 'error' && !/Failed to load resource/.test(m.text())) errors.push(`console: ${m.text()}`);
  });
  return errors;
}

/// Decodes an 8-bit RGB or RGBA, non-interlaced PNG (what the renderer and Chromium's
/// screenshots write) into {width, height, rgb: Uint8Array, rows top to bottom}.
export function decodePng(buffer) {
  assert.equal(buffer.subarray(0, 8).toString('hex'), '89504e470d0a1a0a', 'PNG signature');
  let offset = 8;
  let width = 0, height = 0, channels = 0;
  const idat = [];
  while (offset < buffer.length) {
    const length = buffer.readUInt32BE(offset);
    const type = buffer.toString('latin1', offset + 4, offset + 8);
    const data = buffer.subarray(offset + 8, offset + 8 + length);
    if (type === 'IHDR') {
      width = data.readUInt32BE(0);
      height = data.readUInt32BE(4);
      const depth = data[8], colour = data[9], interlace = data[12];
      assert.equal(depth, 8, 'bit depth');
      assert.ok(colour === 2 || colour === 6, `colour type ${colour}`);
      assert.equal(interlace, 0, 'interlace');
      channels = colour === 2 ? 3 : 4;
    } else if (type === 'IDAT') {
      idat.push(data);
    } else if (type === 'IEND') {
      break;
    }
    offset += 12 + length;
  }
  const raw = zlib.inflateSync(Buffer.concat(idat));
  const stride = width * channels;
  const pixels = new Uint8Array(height * stride);
  const paeth = (a, b, c) => {
    const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
  };
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)];
    const line = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    const out = y * stride, prev = (y - 1) * stride;
    for (let i = 0; i < stride; ++i) {
      const a = i >= channels ? pixels[out + i - channels] : 0;
      const b = y > 0 ? pixels[prev + i] : 0;
      const c = y > 0 && i >= channels ? pixels[prev + i - channels] : 0;
      let v = line[i];
      if (filter === 1) v += a;
      else if (filter === 2) v += b;
      else if (filter === 3) v += (a + b) >> 1;
      else if (filter === 4) v += paeth(a, b, c);
      else assert.equal(filter, 0, `filter ${filter}`);
      pixels[out + i] = v & 255;
    }
  }
  const rgb = new Uint8Array(width * height * 3);
  for (let p = 0; p < width * height; ++p) for (let k = 0; k < 3; ++k) rgb[p * 3 + k] = pixels[p * channels + k];
  return { width, height, rgb };
}

/// The silhouette: pixels that differ from the background grey (any channel by more
/// than 8), as 0/1 per pixel.
export function silhouette(rgb, width, height) {
  const mask = new Uint8Array(width * height);
  for (let p = 0; p < width * height; ++p) {
    const d = Math.max(Math.abs(rgb[3 * p] - BACKGROUND), Math.abs(rgb[3 * p + 1] - BACKGROUND), Math.abs(rgb[3 * p + 2] - BACKGROUND));
    mask[p] = d > 8 ? 1 : 0;
  }
  return mask;
}

/// The preview canvas's pixels on `page` (a complete image: data-state "done"), rows top
/// to bottom, RGB, as {width, height, rgb, view: the canvas's data- attributes}.
export async function readPreviewCanvas(page) {
  const result = await page.evaluate(() => {
    const canvas = document.getElementById('preview');
    const gl = canvas.getContext('webgl2');
    const { width, height } = canvas;
    const rgba = new Uint8Array(width * height * 4);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, rgba);
    let binary = '';
    for (let i = 0; i < rgba.length; i += 0x8000) binary += String.fromCharCode.apply(null, rgba.subarray(i, i + 0x8000));
    return { width, height, rgba: btoa(binary), dataset: { ...canvas.dataset } };
  });
  assert.equal(result.dataset.state, 'done', 'the image was complete when read');
  const { width, height } = result;
  const rgba = Buffer.from(result.rgba, 'base64');
  const rgb = new Uint8Array(width * height * 3);
  for (let y = 0; y < height; ++y) {
    const src = (height - 1 - y) * width * 4; // readPixels' rows start at the bottom
    for (let x = 0; x < width; ++x) for (let k = 0; k < 3; ++k) rgb[(y * width + x) * 3 + k] = rgba[src + 4 * x + k];
  }
  return { width, height, rgb, view: result.dataset };
}

/// Drags the mouse on the preview canvas of `page` from its centre by (dx, dy) CSS
/// pixels in `steps` moves, and leaves the pointer there.
export async function dragPreview(page, dx, dy, steps = 2) {
  const rect = await page.locator('#preview').boundingBox();
  const cx = rect.x + rect.width / 2, cy = rect.y + rect.height / 2;
  await page.mouse.move(cx, cy);
  await page.mouse.down();
  await page.mouse.move(cx + dx, cy + dy, { steps });
  await page.mouse.up();
}

/// Intersection over union of two masks of 0s and 1s of one size (1 when both are empty).
export function iou(a, b) {
  let both = 0, either = 0;
  for (let i = 0; i < a.length; ++i) {
    both += a[i] & b[i];
    either += a[i] | b[i];
  }
  return either ? both / either : 1;
}

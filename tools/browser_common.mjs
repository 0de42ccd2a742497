// What Insula's browser checks share: launching Debian's chromium through npm playwright-core with
// WebGL on SwiftShader (no GPU, nothing downloaded) and, for pages that need real HTTP (web
// workers, relative URLs), a static file server on 127.0.0.1.
// Used by tools/render_gltf_browser.mjs and tools/check_tileset.mjs.
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';

const chromium_args = [
  '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
  '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
];

// Starts chromium (INSULA_CHROMIUM, default /usr/bin/chromium) in a throw-away profile. Returns
// { context, page, close }; close() ends the browser and removes the profile.
export async function launchChromium({ width = 512, height = 512 } = {}) {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'insula-chromium-'));
  let context;
  try {
    context = await chromium.launchPersistentContext(profile, {
      executablePath: process.env.INSULA_CHROMIUM || '/usr/bin/chromium',
      headless: true,
      args: chromium_args,
      viewport: { width, height },
    });
  } catch (error) {
    fs.rmSync(profile, { recursive: true, force: true });
    throw error;
  }
  const page = context.pages()[0] || (await context.newPage());
  const close = async () => {
    try {
      await context.close();
    } finally {
      fs.rmSync(profile, { recursive: true, force: true });
    }
  };
  return { context, page, close };
}

export const content_types = {
  '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript', '.css': 'text/css',
  '.json': 'application/json', '.glb': 'model/gltf-binary', '.gltf': 'model/gltf+json',
  '.png': 'image/png', '.jpg': 'image/jpeg', '.svg': 'image/svg+xml', '.wasm': 'application/wasm',
  '.xml': 'application/xml', '.b3dm': 'application/octet-stream', '.subtree': 'application/octet-stream',
};

// Serves files on http://127.0.0.1:PORT/. mounts maps a URL prefix ('/cesium/') to a folder;
// pages maps an exact path ('/index.html') to a string. Only files under a mount are served.
// Every request is recorded in `log` ({ url, status }). Returns { origin, log, close }.
export async function serveFiles({ mounts = {}, pages = {} } = {}) {
  const log = [];
  const server = http.createServer((request, response) => {
    const url = new URL(request.url, 'http://127.0.0.1');
    const pathname = decodeURIComponent(url.pathname);
    const reply = (status, type, body) => {
      log.push({ url: pathname, status });
      response.writeHead(status, { 'Content-Type': type, 'Access-Control-Allow-Origin': '*',
                                   'Cache-Control': 'no-store' });
      response.end(body);
    };
    if (pages[pathname] !== undefined) return reply(200, 'text/html', pages[pathname]);
    for (const [prefix, folder] of Object.entries(mounts)) {
      if (!pathname.startsWith(prefix)) continue;
      const root = path.resolve(folder);
      const file = path.resolve(root, pathname.slice(prefix.length));
      if (file !== root && !file.startsWith(root + path.sep)) break;
      let body;
      try {
        body = fs.readFileSync(file);
      } catch {
        break;
      }
      return reply(200, content_types[path.extname(file).toLowerCase()] || 'application/octet-stream', body);
    }
    return reply(404, 'text/plain', 'not found');
  });
  await new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(0, '127.0.0.1', resolve);
  });
  const origin = `http://127.0.0.1:${server.address().port}`;
  const close = () => new Promise((resolve) => {
    server.closeAllConnections?.();
    server.close(() => resolve());
  });
  return { origin, log, close };
}

// The scene as the page holds it (the complete JSON of GET /api/scene) and
// the server calls. The server checks everything: the page only edits keys.
'use strict';

const Scene = {
  get(scene, path) {
    return path.split('.').reduce((o, k) => (o == null ? undefined : o[k]), scene);
  },
  set(scene, path, value) {
    const keys = path.split('.');
    let o = scene;
    for (const k of keys.slice(0, -1)) o = o[k] ?? (o[k] = {});
    o[keys[keys.length - 1]] = value;
  },
  // "#rrggbb" from "#rrggbb" or [r, g, b] (the two forms a scene file allows).
  hex(color) {
    if (typeof color === 'string') return color;
    return '#' + color.map((c) => c.toString(16).padStart(2, '0')).join('');
  },
};

// Requests answer {error, key} with a 4xx: thrown as an Error carrying them.
// A Blob (a dropped picture) goes as its bytes, anything else as JSON.
async function api(method, url, body) {
  const raw = body instanceof Blob;
  const res = await fetch(url, {
    method,
    headers: body === undefined ? {} : { 'Content-Type': raw ? body.type || 'application/octet-stream' : 'application/json' },
    body: body === undefined ? undefined : raw ? body : JSON.stringify(body),
  });
  if (!res.ok) {
    let info = { error: res.status + ' ' + res.statusText, key: '' };
    try { info = await res.json(); } catch (_) { /* not JSON */ }
    const err = new Error(info.error);
    err.key = info.key || '';
    err.status = res.status;
    throw err;
  }
  return res;
}

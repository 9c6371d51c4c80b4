#!/usr/bin/env node
// The wingbeat lab's own little web server, for the single-folder download (dist/).
//   node serve.mjs            serves this folder on http://127.0.0.1:8080/ (or a free port)
//   node serve.mjs 9000       another port
// Only this computer can open it (127.0.0.1); it serves GET/HEAD of this folder's files, nothing
// else. The server itself is serve-lib.mjs (a copy of the project's scripts/serve.mjs).
// Needs Node.js 18 or newer and nothing else. Ctrl-C stops it.
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { startServer } from './serve-lib.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const port = Number(process.argv[2] ?? process.env.PORT ?? 8080);
const start = () => startServer(here, Number.isInteger(port) && port >= 0 && port < 65536 ? port : 8080);
start()
  .catch(() => startServer(here, 0))
  .then(({ url }) => {
    console.log(`wingbeat lab: open ${url} in your browser (Ctrl-C stops the server)`);
  })
  .catch((e) => {
    console.error(`wingbeat lab: could not start a server: ${e instanceof Error ? e.message : e}`);
    process.exit(1);
  });

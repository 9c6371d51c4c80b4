// The stand-in Worker shared by the engine tests (engine, engine_requests): it records what is
// posted to it and whether it was terminated, and `reply(data)` delivers a message as the real
// worker would. Not a test file itself (node --test picks up *.test.mjs only).

export function fakeWorker() {
  const w = {
    posted: [],
    terminated: false,
    postMessage(m) {
      w.posted.push(m);
    },
    terminate() {
      w.terminated = true;
    },
    reply(data) {
      w.onmessage({ data });
    },
  };
  return w;
}

// @ts-check
// Host-page helper for the wingbeat lab in an iframe (docs/embedding.md, section iframe).
// A classic script (no module, no build step): include it once on the course page, after the
// iframes, or paste its body into the page.
//
//   <iframe data-wingbeat src="https://lab.example/index.html?embed=1&panels=controls,numbers"
//           title="wingbeat lab" style="width:100%;border:0"></iframe>
//   <script src="https://lab.example/embed-host.js"></script>
//
// 1. Sizes every iframe[data-wingbeat] to the lab's content height (message wingbeat:height),
//    accepting it only from that iframe's window and the origin of its src.
// 2. window.wingbeatLab(iframe) → { set(params), get(), subscribe(fn), unsubscribe() }: the
//    message API as promises (set/get resolve with the wingbeat:state message, reject with the
//    wingbeat:error message).
(function () {
  /** @param {HTMLIFrameElement} frame */
  function originOf(frame) {
    var src = new URL(frame.src, location.href);
    // A frame sandboxed without allow-same-origin speaks from the opaque origin "null".
    var sb = frame.getAttribute('sandbox');
    return sb !== null && !/\ballow-same-origin\b/.test(sb) ? 'null' : src.origin;
  }
  /** @param {MessageEvent} e @param {HTMLIFrameElement} frame */
  function fromLab(e, frame) {
    var d = e.data;
    return (
      e.source === frame.contentWindow &&
      e.origin === originOf(frame) &&
      !!d &&
      typeof d === 'object' &&
      d.version === 1 &&
      typeof d.type === 'string'
    );
  }

  // 1. Auto-height for every iframe[data-wingbeat].
  addEventListener('message', function (e) {
    var frames = document.querySelectorAll('iframe[data-wingbeat]');
    for (var i = 0; i < frames.length; i++) {
      var frame = /** @type {HTMLIFrameElement} */ (frames[i]);
      if (fromLab(e, frame) && e.data.type === 'wingbeat:height' && e.data.height > 0 && e.data.height < 100000) {
        frame.style.height = Math.ceil(e.data.height) + 'px';
      }
    }
  });

  // 2. The message API as promises.
  var seq = 0;
  /** @param {HTMLIFrameElement} frame */
  function wingbeatLab(frame) {
    /** @type {Record<string, { resolve: (v: any) => void, reject: (e: any) => void }>} */
    var waiting = {};
    /** @type {((msg: any) => void) | null} */
    var onResult = null;
    addEventListener('message', function (e) {
      if (!fromLab(e, frame)) return;
      var d = e.data;
      if (d.type === 'wingbeat:result' && onResult) onResult(d);
      var w = d.id != null ? waiting[d.id] : undefined;
      if (!w) return;
      delete waiting[d.id];
      if (d.type === 'wingbeat:error') w.reject(d);
      else w.resolve(d);
    });
    /** @param {string} type @param {Record<string, unknown>} [more] */
    function request(type, more) {
      var id = 'h' + ++seq;
      var target = originOf(frame);
      return new Promise(function (resolve, reject) {
        var msg = Object.assign({ type: 'wingbeat:' + type, version: 1, id: id }, more || {});
        var w = frame.contentWindow;
        if (!w) {
          reject({ type: 'wingbeat:error', code: 'no-frame', message: 'the iframe has no window' });
          return;
        }
        // A request posted while the lab is still starting can be missed: it is sent again once
        // after 3 s (the same id; every request is idempotent). The lab answers within 30 s
        // (else 'no-result'), so silence for 40 s means no lab listens: a 'timeout' error.
        var resend = setTimeout(function () {
          var again = frame.contentWindow;
          if (again) again.postMessage(msg, target === 'null' ? '*' : target);
        }, 3000);
        var give = setTimeout(function () {
          delete waiting[id];
          reject({
            type: 'wingbeat:error',
            code: 'timeout',
            message: 'no reply from the lab within 40 s (is the frame loaded, and is this origin allowed?)',
          });
        }, 40000);
        waiting[id] = {
          resolve: function (d) {
            clearTimeout(resend);
            clearTimeout(give);
            resolve(d);
          },
          reject: function (d) {
            clearTimeout(resend);
            clearTimeout(give);
            reject(d);
          },
        };
        w.postMessage(msg, target === 'null' ? '*' : target);
      });
    }
    return {
      /** @param {Record<string, number | string | string[]>} params */
      set: function (params) {
        return request('set', { params: params });
      },
      get: function () {
        return request('get');
      },
      /** @param {(msg: any) => void} fn */
      subscribe: function (fn) {
        onResult = fn;
        return request('subscribe');
      },
      unsubscribe: function () {
        onResult = null;
        return request('unsubscribe');
      },
    };
  }
  /** @type {any} */ (window).wingbeatLab = wingbeatLab;
})();

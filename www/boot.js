// Shows a bilingual message in the page when the app cannot start: opened from file://
// (browsers block module scripts there), a browser without modules or WebAssembly, or a
// failed download of the module or the wasm (bootstrap.js calls it then). A classic script in
// plain ES5 so that old browsers run it too; loaded from a file (not inline) so that the page
// runs under the strict Content-Security-Policy stated in index.html.
(function () {
  'use strict';

  window.bsvBootError = function (kind, detail) {
    var show = function () {
      var frame = document.getElementById('boot-frame');
      if (frame) frame.parentNode.removeChild(frame);
      var box = document.getElementById('boot-status');
      if (!box) {
        box = document.createElement('div');
        box.id = 'boot-status';
        document.body.insertBefore(box, document.body.firstChild);
      }
      var file = location.protocol === 'file:';
      var en = file
        ? 'This page was opened as a file. Browsers do not run the app from file:// addresses. In the project folder, run "make serve" and open http://127.0.0.1:8000/ instead.'
        : 'The app could not be loaded. Reload the page; if this keeps happening, use a current browser (the app needs JavaScript modules and WebAssembly).';
      var ja = file
        ? 'このページはファイルとして開かれています。ブラウザは file:// のアドレスからはアプリを実行しません。プロジェクトのフォルダーで「make serve」を実行し、http://127.0.0.1:8000/ を開いてください。'
        : 'アプリを読み込めませんでした。ページを再読み込みしてください。それでも表示されない場合は、最新のブラウザーを使ってください（JavaScript モジュールと WebAssembly が必要です）。';
      box.className = 'boot-status boot-error';
      box.setAttribute('role', 'alert');
      box.setAttribute('data-testid', 'boot-error');
      box.setAttribute('data-boot-error', String(kind));
      box.innerHTML = '';
      var add = function (lang, title, text) {
        var h = document.createElement('p');
        h.lang = lang;
        h.className = 'boot-title';
        h.textContent = title;
        var p = document.createElement('p');
        p.lang = lang;
        p.textContent = text;
        box.appendChild(h);
        box.appendChild(p);
      };
      add('en', 'BSV Playground could not start.', en);
      add('ja', 'BSV Playground を起動できませんでした。', ja);
      if (detail && !file) {
        var d = document.createElement('p');
        d.className = 'boot-detail';
        d.textContent = String(detail);
        box.appendChild(d);
      }
    };
    if (document.body) show(); else document.addEventListener('DOMContentLoaded', show);
  };

  // A module script that fails to load (404, blocked) fires `error` on its element; the event
  // does not bubble, so listen in the capture phase. (This replaces an inline onerror=.)
  window.addEventListener('error', function (event) {
    var target = event.target;
    if (target && target.tagName === 'SCRIPT' && target.type === 'module') {
      window.bsvBootError('module');
    }
  }, true);

  if (location.protocol === 'file:') {
    window.bsvBootError('file');
  } else if (!('noModule' in HTMLScriptElement.prototype) || typeof WebAssembly !== 'object') {
    // A browser without module scripts never runs bootstrap.js (this replaces <script nomodule>).
    window.bsvBootError('old-browser');
  }

  // Runs `fn` once the document's body is parsed.
  var whenParsed = function (fn) {
    if (document.readyState !== 'loading') return fn();
    document.addEventListener('DOMContentLoaded', fn);
  };

  // The route's frame, as the app shows it while the page's code loads (src/ui/page_frame.rs):
  // a bar where the header goes, the page's heading and lede in the page's own classes, and the
  // loading line; painted before the app's code is in, so that what a phone paints first is
  // the page's head, where the page will have it. It stands before #app, which it hides
  // (app.css) until the app's own frame replaces it (src/ui/shell.rs). Its words are the
  // route table's (`texts`: the heads' messages in each language, copied from the Fluent files
  // by the build), so that nothing is fetched before this paint.
  // The frame, or null when it is not shown (the app has started or failed, a message is
  // missing).
  var showFrame = function (head, texts) {
    var box = document.getElementById('boot-status');
    var app = document.getElementById('app');
    if (!box || !app || box.getAttribute('data-testid') === 'boot-error') return null;
    var find = function (id) {
      return texts && typeof texts[id] === 'string' ? texts[id] : null;
    };
    var loading = find('page-loading');
    var template = document.createElement('template');
    template.innerHTML = head;
    var named = template.content.querySelectorAll('[data-i18n]');
    for (var n = 0; n < named.length; n++) {
      var value = find(named[n].getAttribute('data-i18n'));
      if (value === null || loading === null) return null;
      named[n].textContent = value;
      named[n].setAttribute('elementtiming', 'bsv-frame');
    }
    var outer = template.content.firstElementChild;
    var line = document.createElement('p');
    line.className = 'page-loading-line';
    var words = document.createElement('span');
    words.textContent = loading;
    var progress = document.createElement('progress');
    progress.className = 'page-loading-progress';
    progress.setAttribute('aria-hidden', 'true');
    line.appendChild(words);
    line.appendChild(progress);
    outer.appendChild(line);
    var bar = document.createElement('div');
    bar.className = 'boot-bar';
    var main = document.createElement('div');
    main.className = 'site-main';
    main.appendChild(template.content);
    line.setAttribute('role', 'status');
    var frame = document.createElement('div');
    frame.id = 'boot-frame';
    frame.className = 'boot-frame';
    frame.setAttribute('data-testid', 'boot-frame');
    frame.appendChild(bar);
    frame.appendChild(main);
    box.parentNode.removeChild(box);
    app.parentNode.insertBefore(frame, app);
    if (window.performance && performance.mark) performance.mark('bsv-boot-frame');
    return frame;
  };

  // Calls `done` once the frame's text is on screen: Element Timing says so; a browser without
  // it (Safari, Firefox) has painted once a task after the next animation frame has run. Also
  // once the app's own frame has replaced it, and at the latest after a second (a tab in the
  // background never paints).
  var onScreen = function (frame, done) {
    var called = false;
    var once = function () {
      if (!called) done();
      called = true;
    };
    setTimeout(once, document.visibilityState === 'hidden' ? 0 : 1000);
    new MutationObserver(function (changes, observer) {
      if (frame.parentNode) return;
      observer.disconnect();
      once();
    }).observe(frame.parentNode, { childList: true });
    var types = (window.PerformanceObserver && PerformanceObserver.supportedEntryTypes) || [];
    if (types.indexOf('element') < 0) {
      if (typeof requestAnimationFrame !== 'function') return once();
      requestAnimationFrame(function () {
        setTimeout(once, 0);
      });
      return;
    }
    new PerformanceObserver(function (list, observer) {
      observer.disconnect();
      once();
    }).observe({ type: 'element', buffered: true });
  };

  // Fetches the main wasm (the HTML's preload of it), paints the route's frame, then asks for
  // the Fluent files the route needs in the visitor's language and the web app manifest, and
  // the route's pack (with its stylesheet) once most of the main wasm is in (the route table at
  // the head of this file in dist/, written by the build). On a slow network every file in
  // flight shares the bandwidth: asked for together, the main wasm ends last and the shell is
  // built only after every byte is in. Asked for in this order, the first paint waits for no
  // request of this script's, the shell is built while the pack arrives, and the pack is asked
  // for one round trip or so before the main wasm ends (a quarter of it left), so the network
  // never idles. bootstrap.js hands `bsvMainWasm` (the response's promise) to the glue's init().
  // The language is chosen as the app chooses it: `?lang=`, the saved choice, the browser's
  // languages, English.
  var table = window.bsvRoutes;
  if (table && location.protocol !== 'file:') {
    var hash = location.hash.replace(/^#\/?/, '');
    var cut = hash.indexOf('?');
    var route = (cut < 0 ? hash : hash.slice(0, cut)).replace(/\/+$/, '') || 'home';
    var query = cut < 0 ? '' : hash.slice(cut + 1);
    var pick = function (tag) {
      var primary = String(tag || '').split(/[-_]/)[0].toLowerCase();
      return primary === 'en' || primary === 'ja' ? primary : null;
    };
    var asked = /(?:^|&)lang=([^&]*)/.exec(query);
    var lang = null;
    try {
      lang = asked ? pick(decodeURIComponent(asked[1])) : null;
    } catch (e) {
      lang = null;
    }
    if (!lang) {
      try {
        lang = pick(localStorage.getItem('bsv.lang'));
      } catch (e) {
        lang = null;
      }
    }
    var preferred = navigator.languages || [navigator.language];
    for (var i = 0; !lang && i < preferred.length; i++) lang = pick(preferred[i]);
    lang = lang || 'en';
    document.documentElement.lang = lang;
    // Projector mode sizes the header by the viewport: its frame waits for the app.
    var projector = false;
    try {
      projector = localStorage.getItem('bsv.projector') === '1';
    } catch (e) {
      projector = false;
    }
    var preload = function (file, as) {
      var link = document.createElement('link');
      link.rel = 'preload';
      link.as = as || 'fetch';
      if (!as) link.crossOrigin = 'anonymous';
      link.href = file;
      document.head.appendChild(link);
    };
    var own = table.strings.routes[route];
    var strings = table.strings.first.concat(own || []);
    // The strings are fetched here, once (a failed request once more), after the frame's paint:
    // the app takes each response from `bsvTexts` (src/ui/lang_files.rs). On a first visit they
    // come in one request, the route's strings pack (scripts/boot-table.mjs), each file's text
    // given to the app as a response of its own; a file the pack lacks, or every file when the
    // pack fails, is fetched by itself. A visit the service worker serves fetches the files,
    // which it holds.
    var texts = {};
    window.bsvTexts = texts;
    var again = function (url) {
      return function (response) {
        return response && response.ok ? response : fetch(url);
      };
    };
    var single = function (url) {
      return fetch(url).then(again(url), again(url));
    };
    var fromPack = function (pack, file, url) {
      return pack.then(function (files) {
        return files && typeof files[file] === 'string'
          ? new Response(files[file], { headers: { 'Content-Type': 'text/plain; charset=utf-8' } })
          : single(url);
      });
    };
    var askStrings = function () {
      var pack = null;
      if (typeof fetch === 'function' && typeof Response === 'function' && own && !served) {
        pack = fetch('locales/' + lang + '/pack_' + route + '.json')
          .then(function (response) {
            return response.ok ? response.json() : null;
          })
          .then(null, function () {
            return null;
          });
      }
      for (var k = 0; k < strings.length; k++) {
        var url = 'locales/' + lang + '/' + strings[k];
        if (pack) {
          texts[url] = fromPack(pack, strings[k], url);
        } else if (typeof fetch === 'function') {
          texts[url] = single(url);
        } else {
          preload(url);
        }
      }
      // The manifest only matters to an install, later: asked for in the head, it would take
      // one of the six connections a browser opens to a server that the stylesheet needs.
      var manifest = document.createElement('link');
      manifest.rel = 'manifest';
      manifest.href = 'www/manifest.webmanifest';
      document.head.appendChild(manifest);
    };
    // Resolves once the route's frame is painted, or at once when there is none to paint. The
    // route's pack is asked for after it (here, and by the app's loader: scripts/split-link.mjs)
    // so that on a first visit the pack never holds up what a phone paints first. A visit the
    // service worker serves does not wait: its files are here.
    var painted = { then: function (fn) { fn(); } };
    var served = navigator.serviceWorker && navigator.serviceWorker.controller;
    if (typeof fetch === 'function' && !served) {
      var framePainted;
      painted = new Promise(function (resolve) {
        framePainted = resolve;
      });
      window.bsvFramePainted = painted;
      if (table.heads && table.heads[route] && !projector && !/(?:^|&)embed=1(?:&|$)/.test(query)) {
        whenParsed(function () {
          var frame = showFrame(table.heads[route], table.texts && table.texts[lang]);
          if (!frame) return framePainted();
          onScreen(frame, framePainted);
        });
      } else {
        framePainted();
      }
    }
    painted.then(askStrings);
    var packAsked = false;
    var askPack = function () {
      // On a slow link (most of the main wasm in only after a second) the pack is asked for at
      // once: the frame is painted by then, or the main thread is busy, and the network must
      // not idle. On a fast one it waits for the frame's paint.
      if (framePainted && performance.now() > 1000) framePainted();
      painted.then(function () {
        if (!packAsked && table.routes[route]) preload('pkg/' + table.routes[route]);
        if (!packAsked && table.sheets && table.sheets[route]) preload(table.sheets[route], 'style');
        packAsked = true;
      });
    };
    if (typeof fetch === 'function' && typeof ReadableStream === 'function') {
      var wasm = fetch(table.main.file);
      window.bsvMainWasm = wasm;
      wasm
        .then(function (response) {
          if (!response.ok || !response.body) return askPack();
          var reader = response.clone().body.getReader();
          var got = 0;
          var read = function () {
            return reader.read().then(function (chunk) {
              if (chunk.done) return askPack();
              got += chunk.value.length;
              if (got < table.main.bytes * 0.75) return read();
              askPack();
              return reader.cancel();
            });
          };
          return read();
        })
        .then(null, askPack);
    } else {
      askPack();
    }
  }
})();

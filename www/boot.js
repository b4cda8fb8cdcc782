// Shows a bilingual message in the page when the app cannot start: opened from file://
// (browsers block module scripts there), a browser without modules or WebAssembly, or a
// failed download of the module or the wasm (bootstrap.js calls it then). A classic script in
// plain ES5 so that old browsers run it too; loaded from a file (not inline) so that the page
// runs under the strict Content-Security-Policy stated in index.html.
(function () {
  'use strict';

  window.bsvBootError = function (kind, detail) {
    var show = function () {
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

  // Fetches the main wasm (the HTML's preload of it) and preloads the Fluent files the route
  // needs in the visitor's language at once, and the route's pack once most of the main wasm
  // is in (the route table at the head of this file in dist/, written by the build). On a slow
  // network every file in flight shares the bandwidth: asked for together, the main wasm ends
  // last and the shell is built only after every byte is in. Asked for in this order, the
  // shell is built while the pack arrives; the pack is asked for one round trip or so before
  // the main wasm ends (a quarter of it left), so the network never idles. bootstrap.js hands
  // `bsvMainWasm` (the response's promise) to the glue's init(). The language is chosen as the
  // app chooses it: `?lang=`, the saved choice, the browser's languages, English.
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
    var preload = function (file) {
      var link = document.createElement('link');
      link.rel = 'preload';
      link.as = 'fetch';
      link.crossOrigin = 'anonymous';
      link.href = file;
      document.head.appendChild(link);
    };
    var strings = table.strings.first.concat(table.strings.routes[route] || []);
    for (var k = 0; k < strings.length; k++) preload('locales/' + (lang || 'en') + '/' + strings[k]);
    var packAsked = false;
    var askPack = function () {
      if (!packAsked && table.routes[route]) preload('pkg/' + table.routes[route]);
      packAsked = true;
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

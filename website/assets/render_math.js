// Renders the write-up's TeX spans with KaTeX at build time, so the page needs no JavaScript.
// Input: a JSON file [{tex, display}]; output on stdout: [{html} | {error}] in the same order.
'use strict';
const fs = require('fs');
const katex = require('katex');

const spans = JSON.parse(fs.readFileSync(process.argv[2], 'utf8'));
const out = spans.map(({ tex, display }) => {
  try {
    return { html: katex.renderToString(tex, { displayMode: display, throwOnError: true, output: 'html' }) };
  } catch (e) {
    return { error: String(e.message || e) };
  }
});
process.stdout.write(JSON.stringify(out));

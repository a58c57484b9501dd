// Debian's headless Chromium for the page tests (viewer, live, preview): one set of flags, so a
// flag that a Chromium update needs is changed once. CHROMIUM names the browser (viewer_test.sh).
'use strict';
const puppeteer = require('puppeteer-core');

/// Starts the browser with its profile in `profileDir` and pages of `viewport` size.
function launchChromium(profileDir, viewport = { width: 1400, height: 900 }) {
  return puppeteer.launch({
    executablePath: process.env.CHROMIUM,
    headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync',
           `--user-data-dir=${profileDir}`],
    defaultViewport: viewport,
  });
}

module.exports = { launchChromium };

// Pages in the extension's webviews: a Content-Security-Policy that lets only the page's own
// inline scripts (by nonce) and styles run, and nothing load from the network.
import { randomBytes } from 'node:crypto';

export function withPolicy(html: string): string {
  const nonce = randomBytes(16).toString('base64');
  const policy = `default-src 'none'; img-src data:; style-src 'unsafe-inline'; script-src 'nonce-${nonce}';`;
  return html
    .replace(/<head>/, `<head>\n<meta http-equiv="Content-Security-Policy" content="${policy}">`)
    .replace(/<script>/g, `<script nonce="${nonce}">`);
}

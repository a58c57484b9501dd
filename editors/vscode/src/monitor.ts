// The live page of a running robot (`gfec monitor CHART --http 127.0.0.1:PORT`, docs/live.md) in
// a panel: the page the monitor serves, in a frame. The monitor binds to loopback, so only a
// loopback http URL is taken; VS Code maps it when the window is remote (asExternalUri).
import * as vscode from 'vscode';

/** The URL as typed when it is a loopback http(s) address, else why not. */
export function loopbackUrl(text: string): { url?: URL; error?: string } {
  let url: URL;
  try {
    url = new URL(text.trim());
  } catch {
    return { error: 'not a URL (gfec monitor --http prints it: http://127.0.0.1:PORT/)' };
  }
  if (url.protocol !== 'http:' && url.protocol !== 'https:') return { error: 'not an http URL' };
  if (!['127.0.0.1', 'localhost', '[::1]'].includes(url.hostname)) return { error: 'gfec monitor serves loopback only: 127.0.0.1, localhost or [::1]' };
  return { url };
}

/** The panel's page: the monitor's page in a frame, and nothing else allowed. */
export function monitorPage(src: string): string {
  const origin = new URL(src).origin;
  const quoted = src.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');
  return `<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'; frame-src ${origin}; style-src 'unsafe-inline';">
<style>html, body, iframe { margin: 0; padding: 0; border: 0; width: 100%; height: 100%; overflow: hidden; }</style>
</head><body><iframe src="${quoted}" title="gfec monitor"></iframe></body></html>`;
}

export async function openLiveMonitor(): Promise<void> {
  const text = await vscode.window.showInputBox({
    title: 'gfec: the live monitor\'s address', prompt: 'The URL `gfec monitor CHART --http` printed',
    value: 'http://127.0.0.1:', validateInput: (v) => loopbackUrl(v).error ?? null,
  });
  if (text === undefined) return;
  const { url } = loopbackUrl(text);
  if (!url) return;
  const external = await vscode.env.asExternalUri(vscode.Uri.parse(url.toString()));
  const panel = vscode.window.createWebviewPanel('gfec.monitor', `Live: ${url.host}`, vscode.ViewColumn.Beside,
    { enableScripts: true, localResourceRoots: [] });
  // Scripts on: the frame's page (the monitor's) needs them; this page has none (its policy).
  panel.webview.html = monitorPage(external.toString(true));
}

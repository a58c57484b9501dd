// A run replay in a panel: `gfec run CHART --inputs CSV --html OUT` (docs/viewer.md), and OUT,
// a self-contained page, shown as it is.
import { execFile } from 'node:child_process';
import * as fs from 'node:fs';
import * as path from 'node:path';
import * as vscode from 'vscode';
import { gfecPath } from './languages';
import { withPolicy } from './webview';

export async function openRunReplay(context: vscode.ExtensionContext, target?: vscode.Uri): Promise<void> {
  const editor = vscode.window.activeTextEditor;
  const chart = target ?? editor?.document.uri;
  if (!chart || chart.scheme !== 'file') {
    void vscode.window.showInformationMessage('gfec: open a chart file (.sfc, .fsm) to replay a run of it.');
    return;
  }
  if (editor && editor.document.uri.toString() === chart.toString() && editor.document.isDirty) await editor.document.save();
  const picked = await vscode.window.showOpenDialog({
    title: 'The run\'s inputs (a CSV of interface values per tick)', canSelectMany: false,
    defaultUri: vscode.Uri.file(path.dirname(chart.fsPath)), filters: { 'CSV': ['csv'] },
  });
  if (!picked || picked.length === 0) return;
  const storage = context.globalStorageUri.fsPath;
  fs.mkdirSync(storage, { recursive: true });
  const out = path.join(storage, `${path.basename(chart.fsPath)}.run.html`);
  const args = ['run', chart.fsPath, '--inputs', picked[0].fsPath, '--html', out];
  const error = await new Promise<string | null>((resolve) => {
    execFile(gfecPath(), args, { maxBuffer: 64 << 20 }, (err, _stdout, stderr) => resolve(err ? (stderr.trim() || err.message) : null));
  });
  if (error !== null) {
    void vscode.window.showErrorMessage(`gfec run failed: ${error}`);
    return;
  }
  const panel = vscode.window.createWebviewPanel('gfec.replay', `Run: ${path.basename(chart.fsPath)}`, vscode.ViewColumn.Beside,
    { enableScripts: true, localResourceRoots: [] });
  panel.webview.html = withPolicy(fs.readFileSync(out, 'utf8'));
}

// The live chart preview: a webview beside the editor showing the viewer's preview page
// (viewer/page/preview.html, bundled as media/preview.html). It follows the active gfec editor,
// asks the server for `gfec/chartPicture` again as the user types (debounced), keeps the last
// good picture while the text does not compile, lights the element under the cursor, and opens
// the source range of an element the user clicks. Messages: viewer/page/preview.js.
import * as fs from 'node:fs';
import * as path from 'node:path';
import * as vscode from 'vscode';
import type { LanguageClient } from 'vscode-languageclient/node';
import { isChart, isGfec } from './languages';
import { withPolicy } from './webview';

interface LspRange { start: { line: number; character: number }; end: { line: number; character: number } }
interface ChartElement { node: string; kind: string; name: string; uri: string; range: LspRange }
interface ChartPicture { version: number | null; svg: string | null; note: string; elements: ChartElement[] }

export class ChartPreview implements vscode.Disposable {
  private panel: vscode.WebviewPanel | undefined;
  private document: vscode.TextDocument | undefined;   // the text the picture is of
  private timer: NodeJS.Timeout | undefined;
  private asked = 0;                                    // requests made; a late answer is dropped
  private broken = false;                               // the last answer had no picture
  private lastNote = '';
  private readonly subscriptions: vscode.Disposable[] = [];

  constructor(private readonly context: vscode.ExtensionContext,
              private readonly client: () => LanguageClient | undefined) {
    this.subscriptions.push(
      // The picture depends on the files the chart imports too (interfaces, sub-charts): any
      // gfec text's change asks again.
      vscode.workspace.onDidChangeTextDocument((e) => {
        if (this.panel && this.document && (e.document === this.document || isGfec(e.document.languageId))) this.schedule();
      }),
      // The panel follows the active chart; an interface or a test file leaves it as it is.
      vscode.window.onDidChangeActiveTextEditor((editor) => {
        if (this.panel && editor && isChart(editor.document.languageId) && editor.document !== this.document) {
          this.document = editor.document;
          void this.refresh();
        }
      }),
      vscode.window.onDidChangeTextEditorSelection((e) => {
        if (this.panel && e.textEditor.document === this.document) this.postCursor(e.textEditor);
      }),
      vscode.languages.onDidChangeDiagnostics((e) => {
        if (this.panel && this.broken && this.document && e.uris.some((u) => u.toString() === this.document!.uri.toString()))
          this.postProblems(this.lastNote);
      }),
    );
  }

  open(): void {
    const editor = vscode.window.activeTextEditor;
    if (!editor || !isChart(editor.document.languageId)) {
      void vscode.window.showInformationMessage('gfec: open a chart (.sfc, .fsm, .plan) to preview it.');
      return;
    }
    this.document = editor.document;
    if (this.panel) {
      this.panel.reveal(vscode.ViewColumn.Beside, true);
      void this.refresh();
      return;
    }
    this.panel = vscode.window.createWebviewPanel('gfec.preview', 'Chart preview', { viewColumn: vscode.ViewColumn.Beside, preserveFocus: true },
      { enableScripts: true, retainContextWhenHidden: true, localResourceRoots: [] });
    const page = fs.readFileSync(path.join(this.context.extensionPath, 'media', 'preview.html'), 'utf8');
    this.panel.webview.html = withPolicy(page);
    this.panel.webview.onDidReceiveMessage((m) => this.onMessage(m), undefined, this.subscriptions);
    this.panel.onDidDispose(() => { this.panel = undefined; }, undefined, this.subscriptions);
  }

  private onMessage(m: { type: string; uri?: string; range?: LspRange }): void {
    if (m.type === 'ready') {
      void this.refresh();
    } else if (m.type === 'reveal' && m.uri && m.range) {
      void this.reveal(vscode.Uri.parse(m.uri), m.range);
    }
  }

  private async reveal(uri: vscode.Uri, r: LspRange): Promise<void> {
    const range = new vscode.Range(r.start.line, r.start.character, r.end.line, r.end.character);
    // Into the editor the picture is of when the element is in its file; beside it otherwise.
    const shown = vscode.window.visibleTextEditors.find((e) => e.document.uri.toString() === uri.toString());
    const doc = await vscode.workspace.openTextDocument(uri);
    const editor = await vscode.window.showTextDocument(doc, { viewColumn: shown?.viewColumn ?? vscode.ViewColumn.One, preserveFocus: false });
    editor.selection = new vscode.Selection(range.start, range.start);
    editor.revealRange(range, vscode.TextEditorRevealType.InCenterIfOutsideViewport);
  }

  private schedule(): void {
    if (this.timer) clearTimeout(this.timer);
    const delay = vscode.workspace.getConfiguration('gfec').get<number>('preview.delay') ?? 300;
    this.timer = setTimeout(() => void this.refresh(), delay);
  }

  private async refresh(): Promise<void> {
    const panel = this.panel, doc = this.document, client = this.client();
    if (!panel || !doc) return;
    panel.title = `Chart: ${path.basename(doc.uri.fsPath)}`;
    if (!client || !client.isRunning()) {
      this.broken = true;
      this.lastNote = 'the language server (gfec lsp) is not running: see the gfec.path setting';
      this.postProblems(this.lastNote);
      return;
    }
    const ticket = ++this.asked;
    let result: ChartPicture;
    try {
      result = await client.sendRequest<ChartPicture>('gfec/chartPicture', { textDocument: { uri: doc.uri.toString() } });
    } catch (e) {
      if (ticket !== this.asked) return;
      this.broken = true;
      this.lastNote = `no picture: ${e instanceof Error ? e.message : String(e)}`;
      this.postProblems(this.lastNote);
      return;
    }
    if (ticket !== this.asked || panel !== this.panel) return;
    this.broken = !result.svg;
    if (result.svg) {
      void panel.webview.postMessage({ type: 'picture', svg: result.svg, note: result.note, elements: result.elements ?? [],
                                       title: `${path.basename(doc.uri.fsPath)}${result.note ? ' — ' + result.note : ''}` });
      const editor = vscode.window.visibleTextEditors.find((e) => e.document === doc);
      if (editor) this.postCursor(editor);
    } else {
      this.lastNote = result.note || 'the text does not compile';
      this.postProblems(this.lastNote);
    }
  }

  // The errors VS Code holds for the text (the server published them): listed over the picture.
  private postProblems(note: string): void {
    if (!this.panel || !this.document) return;
    const problems = vscode.languages.getDiagnostics(this.document.uri)
      .filter((d) => d.severity === vscode.DiagnosticSeverity.Error)
      .map((d) => ({ uri: this.document!.uri.toString(), message: d.message,
                     range: { start: { line: d.range.start.line, character: d.range.start.character },
                              end: { line: d.range.end.line, character: d.range.end.character } } }));
    void this.panel.webview.postMessage({ type: 'problems', note, problems });
  }

  private postCursor(editor: vscode.TextEditor): void {
    const p = editor.selection.active;
    void this.panel?.webview.postMessage({ type: 'cursor', uri: editor.document.uri.toString(),
                                           position: { line: p.line, character: p.character } });
  }

  dispose(): void {
    if (this.timer) clearTimeout(this.timer);
    this.panel?.dispose();
    for (const s of this.subscriptions) s.dispose();
  }
}

// The extension's entry: the language client running `gfec lsp`, the chart preview, the run
// replay and the live monitor (docs/editors.md, "VS Code").
import * as vscode from 'vscode';
import { LanguageClient, LanguageClientOptions, ServerOptions, TransportKind } from 'vscode-languageclient/node';
import { LANGUAGES, gfecPath } from './languages';
import { ChartPreview } from './preview';
import { openLiveMonitor } from './monitor';
import { openRunReplay } from './replay';

let client: LanguageClient | undefined;

function makeClient(): LanguageClient {
  const server: ServerOptions = { command: gfecPath(), args: ['lsp'], transport: TransportKind.stdio };
  // The server's own settings (docs/editors.md, "Starting the server"): given only when set, so a
  // server's defaults stay its own.
  const config = vscode.workspace.getConfiguration('gfec');
  const initializationOptions: { includeDirs?: string[]; warnings?: string[]; period?: string } = {};
  const includeDirs = config.get<string[]>('includeDirs') ?? [];
  const warnings = config.get<string[]>('warnings') ?? [];
  const period = config.get<string>('period') ?? '';
  if (includeDirs.length > 0) initializationOptions.includeDirs = includeDirs;
  if (warnings.length > 0) initializationOptions.warnings = warnings;
  if (period !== '') initializationOptions.period = period;
  const options: LanguageClientOptions = {
    // IEC 61131-3 structured text by its extension, whatever language mode another extension
    // gives it: the server checks it as gfec --check does (docs/iec.md).
    documentSelector: [...LANGUAGES.map((language) => ({ language })), { scheme: 'file', pattern: '**/*.st' }],
    initializationOptions,
    // Files of the workspace the server reads without their being open (imports, .test files
    // naming a chart): it hears when they change on disk.
    synchronize: { fileEvents: vscode.workspace.createFileSystemWatcher('**/*.{sfc,fsm,plan,toolbox,iface,test,st}') },
  };
  // The id 'gfec' makes vscode-languageclient read the setting gfec.trace.server itself.
  return new LanguageClient('gfec', 'gfec language server', server, options);
}

async function startClient(): Promise<void> {
  client = makeClient();
  try {
    await client.start();
  } catch (e) {
    const message = e instanceof Error ? e.message : String(e);
    void vscode.window.showErrorMessage(
      `gfec: could not start '${gfecPath()} lsp' (${message}). Set gfec.path to the gfec executable.`);
  }
}

async function restartClient(): Promise<void> {
  const old = client;
  client = undefined;
  if (old) await old.stop().catch(() => undefined);
  await startClient();
}

export async function activate(context: vscode.ExtensionContext): Promise<void> {
  const preview = new ChartPreview(context, () => client);
  context.subscriptions.push(
    preview,
    vscode.commands.registerCommand('gfec.openPreview', () => preview.open()),
    vscode.commands.registerCommand('gfec.openRunReplay', (uri?: vscode.Uri) => openRunReplay(context, uri)),
    vscode.commands.registerCommand('gfec.openLiveMonitor', openLiveMonitor),
    vscode.commands.registerCommand('gfec.restartServer', restartClient),
    vscode.workspace.onDidChangeConfiguration((e) => {
      if (['gfec.path', 'gfec.includeDirs', 'gfec.warnings', 'gfec.period'].some((k) => e.affectsConfiguration(k)))
        void restartClient();
    }),
  );
  await startClient();
}

export async function deactivate(): Promise<void> {
  if (client) await client.stop();
}

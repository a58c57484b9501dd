// The language ids of gfec's six file kinds (package.json's `contributes.languages`) and the
// executable the settings name.
import * as vscode from 'vscode';

export const LANGUAGES = ['gfec-sfc', 'gfec-fsm', 'gfec-plan', 'gfec-toolbox', 'gfec-iface', 'gfec-test'];

export function isGfec(languageId: string): boolean {
  return LANGUAGES.includes(languageId);
}

/** The kinds that have a picture: charts and plans. */
export function isChart(languageId: string): boolean {
  return ['gfec-sfc', 'gfec-fsm', 'gfec-plan'].includes(languageId);
}

/** gfec.path: a path, or a name looked up on PATH. */
export function gfecPath(): string {
  return vscode.workspace.getConfiguration('gfec').get<string>('path') || 'gfec';
}

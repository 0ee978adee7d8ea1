// Requests that try to read outside the served root, written as raw request lines because an
// HTTP client would normalise most of them away before they left. The fixture's secret sits
// at root/../secret.txt and root/../outside/inner.json.

export const TRAVERSAL_TARGETS: readonly string[] = [
  '/../secret.txt',
  '/../../../../../../etc/passwd',
  '/sub/../../secret.txt',
  '/%2e%2e/secret.txt',
  '/%2E%2E/secret.txt',
  '/.%2e/secret.txt',
  '/%2e%2e%2fsecret.txt',
  '/..%2fsecret.txt',
  '/..%2Fsecret.txt',
  '/sub/..%2f..%2fsecret.txt',
  '/%252e%252e/secret.txt', // double-encoded dots
  '/%252e%252e%252fsecret.txt', // double-encoded dots and slash
  '/..%252fsecret.txt',
  '/..\\secret.txt', // backslash
  '/..%5csecret.txt',
  '/..%5Csecret.txt',
  '/sub\\..\\..\\secret.txt',
  '/%c0%ae%c0%ae/secret.txt', // overlong UTF-8 dots
  '/index.json%00/../../secret.txt', // NUL
  '/%00../secret.txt',
  '/link-out.txt', // symlink to root/../secret.txt
  '/link-dir/inner.json', // symlink to root/../outside
  '/.hidden.json', // a dotfile in the root, holding the secret too
  'http://127.0.0.1/../secret.txt', // absolute-form
];

export function rawGet(target: string): string {
  return `GET ${target} HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n`;
}

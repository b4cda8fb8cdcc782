// The flags every headless Chromium of the tests and benches starts with: no sandbox (root),
// no GPU, and none of Chromium's own network traffic (this machine reaches no other host).
export const CHROMIUM_ARGS = [
  '--no-sandbox',
  '--disable-gpu',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--disable-quic',
];

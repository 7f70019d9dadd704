/**
 * Just enough of XMLHttpRequest, over Node's fetch, for the xAPI client inside @xapi/cmi5 (its
 * bundled HTTP library speaks only XMLHttpRequest), so the cmi5 runtime can talk to a loopback
 * record store in a unit test.
 */
export class NodeXhr {
  onloadend: (() => void) | null = null;
  onerror: ((e: unknown) => void) | null = null;
  onabort: (() => void) | null = null;
  ontimeout: (() => void) | null = null;
  onreadystatechange: (() => void) | null = null;
  readyState = 0;
  status = 0;
  statusText = '';
  responseText = '';
  response: unknown = '';
  responseType = '';
  responseURL = '';
  timeout = 0;
  withCredentials = false;
  private method = 'GET';
  private url = '';
  private headers: Record<string, string> = {};
  private received = '';

  open(method: string, url: string): void {
    this.method = method;
    this.url = url;
    this.readyState = 1;
  }
  setRequestHeader(name: string, value: string): void {
    this.headers[name] = value;
  }
  getAllResponseHeaders(): string {
    return this.received;
  }
  addEventListener(): void {}
  abort(): void {}
  send(body?: string | null): void {
    fetch(this.url, { method: this.method, headers: this.headers, body: body ?? undefined }).then(
      async (r) => {
        this.status = r.status;
        this.statusText = r.statusText;
        this.responseURL = r.url;
        this.responseText = await r.text();
        this.response = this.responseText;
        this.received = [...r.headers].map(([k, v]) => `${k}: ${v}`).join('\r\n');
        this.readyState = 4;
        this.onreadystatechange?.();
        this.onloadend?.();
      },
      (e: unknown) => {
        this.readyState = 4;
        this.onerror?.(e);
      },
    );
  }
}

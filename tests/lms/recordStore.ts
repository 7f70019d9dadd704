/**
 * A loopback cmi5 record store for unit tests (127.0.0.1 only): the fetch URL hands out the auth
 * token, the state resource keeps documents (LMS.LaunchData among them) per state id, and every
 * statement is recorded. `refuse` makes it answer statements with 500.
 */
import { createServer, type Server } from 'node:http';

export interface RecordStore {
  origin: string;
  statements: Record<string, any>[];
  /** State documents by activity, registration and state id (LMS.LaunchData is served, not kept). */
  state: Map<string, unknown>;
  refuse: { statements: boolean };
  close(): Promise<void>;
}

const TOKEN = Buffer.from('au:secret').toString('base64');

export async function recordStore(launchData: Record<string, unknown>): Promise<RecordStore> {
  const statements: Record<string, any>[] = [];
  const state = new Map<string, unknown>();
  const refuse = { statements: false };
  const server: Server = createServer((req, res) => {
    const chunks: Buffer[] = [];
    req.on('data', (c: Buffer) => chunks.push(c));
    req.on('end', () => {
      const body = Buffer.concat(chunks).toString('utf8');
      const url = new URL(req.url ?? '/', 'http://127.0.0.1');
      const json = (code: number, x: unknown) => {
        res.writeHead(code, { 'content-type': 'application/json', 'x-experience-api-version': '1.0.3' });
        res.end(JSON.stringify(x));
      };
      if (url.pathname === '/fetch' && req.method === 'POST') return json(200, { 'auth-token': TOKEN });
      if (req.headers.authorization !== `Basic ${TOKEN}`) return json(401, { error: 'no token' });
      if (url.pathname === '/xapi/activities/state') {
        const id = url.searchParams.get('stateId');
        // documents are kept per activity and registration (the agent is the one learner's)
        const scope = `${url.searchParams.get('activityId')}|${url.searchParams.get('registration')}|`;
        const mine = [...state.keys()].filter((k) => k.startsWith(scope)).map((k) => k.slice(scope.length));
        if (req.method === 'GET' && id === 'LMS.LaunchData') return json(200, launchData);
        if (req.method === 'GET' && id === null) return json(200, ['LMS.LaunchData', ...mine]);
        if (req.method === 'GET' && id !== null && state.has(scope + id))
          return json(200, state.get(scope + id));
        if ((req.method === 'PUT' || req.method === 'POST') && id !== null) {
          state.set(scope + id, JSON.parse(body));
          res.writeHead(204);
          return res.end();
        }
        return json(404, {});
      }
      if (url.pathname === '/xapi/agents/profile') return json(200, {});
      if (url.pathname === '/xapi/statements' && (req.method === 'POST' || req.method === 'PUT')) {
        if (refuse.statements) return json(500, { error: 'store unavailable' });
        const got = JSON.parse(body) as Record<string, any> | Record<string, any>[];
        const list = Array.isArray(got) ? got : [got];
        statements.push(...list);
        return json(
          200,
          list.map((_, i) => `id-${statements.length}-${i}`),
        );
      }
      return json(404, {});
    });
  });
  await new Promise<void>((ok) => server.listen(0, '127.0.0.1', ok));
  const port = (server.address() as { port: number }).port;
  return {
    origin: `http://127.0.0.1:${port}`,
    statements,
    state,
    refuse,
    close: () =>
      new Promise<void>((ok) => {
        server.closeAllConnections();
        server.close(() => ok());
      }),
  };
}

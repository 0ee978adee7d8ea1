// What a server sent, response by response: the bytes on the wire (status line, headers and
// the body, gzip-encoded when the client took the .gz sibling) and when the response was
// finished, on the wall clock that Chromium's performance.timeOrigin + performance.now() also
// keeps. Counted at the socket: the handler writes its headers with writeHead, which
// getHeader does not see, and Chromium sends one request at a time on a connection.
import type { Server } from 'node:http';

export interface Sent {
  /** Milliseconds since the epoch. */
  at: number;
  path: string;
  bytes: number;
}

/** A log that fills as `server` answers; clear it with `log.length = 0`. */
export function logResponses(server: Server): Sent[] {
  const log: Sent[] = [];
  server.on('request', (req, res) => {
    // This listener runs after the handler's first, synchronous part, which sends nothing yet.
    const socket = req.socket;
    const before = socket.bytesWritten;
    res.on('finish', () => {
      log.push({ at: performance.timeOrigin + performance.now(), path: req.url ?? '', bytes: socket.bytesWritten - before });
    });
  });
  return log;
}

// Closes connections that hold the server without making progress: one that sends no request
// head in time (silent, or slowloris), one idle too long between requests, and one whose
// client stopped reading a response. Node 20's own socket timeouts cannot be relied on for
// this: with a connectionsCheckingInterval shorter than them they never fired for a silent
// connection or a stalled reader here, so one interval checks every connection itself.
import type { Server } from 'node:http';
import type { Socket } from 'node:net';

export interface WatchdogLimits {
  headersMs: number; // from connect to the first complete request head
  keepAliveMs: number; // from a response's end to the next request head (plus headersMs)
  stallMs: number; // a response in flight with no bytes moving either way
  checkEveryMs: number;
}

interface Watch {
  inFlight: number;
  served: number;
  waitingSince: number;
  lastProgress: number;
  counters: string;
}

// Bytes libuv has queued but the kernel has not taken yet: the only sign that a large write
// is still draining. Not in Node's typings, hence the narrow cast.
function queuedBytes(socket: Socket): number {
  return (socket as unknown as { _handle?: { writeQueueSize?: number } })._handle?.writeQueueSize ?? 0;
}

function countersOf(socket: Socket): string {
  return `${socket.bytesRead}:${socket.bytesWritten}:${socket.writableLength}:${queuedBytes(socket)}`;
}

/** Starts watching `server`'s connections until the server closes. */
export function watchConnections(server: Server, limits: WatchdogLimits): void {
  const watched = new Map<Socket, Watch>();

  server.on('connection', (socket: Socket) => {
    const now = Date.now();
    watched.set(socket, { inFlight: 0, served: 0, waitingSince: now, lastProgress: now, counters: '' });
    socket.once('close', () => watched.delete(socket));
  });

  server.on('request', (req, res) => {
    const w = watched.get(req.socket);
    if (!w) return;
    w.inFlight++;
    w.lastProgress = Date.now();
    res.once('close', () => {
      w.inFlight--;
      w.served++;
      if (w.inFlight === 0) w.waitingSince = Date.now();
    });
  });

  const timer = setInterval(() => {
    const now = Date.now();
    for (const [socket, w] of watched) {
      if (w.inFlight === 0) {
        // A deadline, not an inactivity limit: a slowloris client is never inactive.
        const limit = w.served === 0 ? limits.headersMs : limits.keepAliveMs + limits.headersMs;
        if (now - w.waitingSince > limit) socket.destroy();
        continue;
      }
      const counters = countersOf(socket);
      if (counters !== w.counters) {
        w.counters = counters;
        w.lastProgress = now;
      } else if (now - w.lastProgress > limits.stallMs) {
        socket.destroy();
      }
    }
  }, limits.checkEveryMs);
  timer.unref();
  server.once('close', () => clearInterval(timer));
}

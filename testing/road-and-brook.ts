// Two hand-made lines for the line tests: a road of two polylines (a T: 3 + 2 points) whose
// middle vertex leaves at z 20.125, and a brook of one polyline (3 points) whose middle vertex
// leaves at z 5. Coordinates near national grid values, exact in float32 relative to whole metres.
import type { LineRecord } from '../format/line-record.js';

export function roadAndBrook(): LineRecord[] {
  return [
    {
      classIndex: 4, rule: 9, feature: 17, zStart: 10.5, zEnd: 40.25,
      paths: [Float64Array.of(181000.5, 457000.25, 181010.5, 457000.25, 181020.5, 457000.25), Float64Array.of(181010.5, 457000.25, 181010.5, 457030.75)],
      leaveZ: [Float64Array.of(40.25, 20.125, 40.25), Float64Array.of(40.25, 40.25)],
    },
    {
      classIndex: 7, rule: 300, feature: -1, zStart: 3, zEnd: 12,
      paths: [Float64Array.of(181005, 456990, 181006, 456995, 181030, 457001)],
      leaveZ: [Float64Array.of(12, 5, 12)],
    },
  ];
}

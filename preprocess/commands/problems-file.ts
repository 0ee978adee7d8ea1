// --problems <file.geojson>: when the input is refused, the places of its problems are
// written there (and nothing else is written).
import { writeFileAtomic } from '../io/atomic-write.js';
import { checkOutputPath } from '../io/output-path.js';
import { problemsGeoJson } from '../io/problems-geojson.js';
import { InputProblems } from '../io/problems.js';

export const problemsUsage = `  --problems <file.geojson> when the input is refused, write the places of its problems there
                            (points with kind, feature and message; open it beside the data in QGIS)
  --max-problems <n>        name at most n problems of a refused input (default 50)
  --drop-duplicates         drop the later of two exactly equal polygons (counted), instead of refusing`;

/** Runs `work`; a refusal writes its problems' places to `file` (when given) and says where. */
export async function withProblemsFile<T>(file: string | undefined, work: () => Promise<T>): Promise<T> {
  if (file) await checkOutputPath(file, 'file', '--problems');
  try {
    return await work();
  } catch (err) {
    if (!(err instanceof InputProblems)) throw err;
    if (file) {
      await writeFileAtomic(file, problemsGeoJson(err));
      err.message += `\n(the places of the problems are in ${file})`;
    } else if (err.problems.length > 1) {
      err.message += '\n(--problems <file.geojson> writes their places, to see them in a GIS)';
    }
    throw err;
  }
}

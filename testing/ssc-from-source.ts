// bin/ssc.js runs the compiled CLI; the tests run this, the same main() from source.
import { main } from '../preprocess/cli.js';

process.exitCode = await main(process.argv.slice(2));

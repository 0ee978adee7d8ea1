// ssc: the command line of the vario-scale map's preprocessing.
import { FormatError } from '../format/format-error.js';
import { InputError } from './io/errors.js';
import { fsReason, isFsError, OutputError } from './io/output-path.js';
import { UsageError } from './commands/args.js';

interface Command {
  usage: string;
  run(argv: string[]): Promise<void>;
}

const commands: Record<string, () => Promise<Command>> = {
  generalize: () => import('./commands/generalize.js'),
  map: () => import('./commands/map.js'),
  serve: () => import('./commands/serve.js'),
  build: () => import('./commands/build.js'),
  slice: () => import('./commands/slice.js'),
  inspect: () => import('./commands/inspect.js'),
  style: () => import('./commands/style.js'),
};

function help(): string {
  return `usage: ssc <command> [options]\ncommands: ${Object.keys(commands).join(', ')}\nssc <command> --help shows a command's options\n`;
}

export async function main(argv: string[]): Promise<number> {
  const [name, ...rest] = argv;
  if (!name || name === '--help' || name === '-h' || name === 'help') {
    process.stdout.write(help());
    return name ? 0 : 2;
  }
  const load = commands[name];
  if (!load) {
    process.stderr.write(`ssc: unknown command ${JSON.stringify(name)}\n${help()}`);
    return 2;
  }
  const cmd = await load();
  if (rest.includes('--help') || rest.includes('-h')) {
    process.stdout.write(cmd.usage + '\n');
    return 0;
  }
  try {
    await cmd.run(rest);
    return 0;
  } catch (err) {
    if (err instanceof UsageError || (err instanceof TypeError && (err as { code?: string }).code?.startsWith('ERR_PARSE_ARGS'))) {
      process.stderr.write(`ssc ${name}: ${(err).message}\n${cmd.usage}\n`);
      return 2;
    }
    // A bad input or a file that breaks its format (a corrupt tGAP or cube): the user can act.
    if (err instanceof InputError || err instanceof FormatError || err instanceof OutputError) {
      process.stderr.write(`ssc ${name}: ${err.message}\n`);
      return 1;
    }
    // Any other path that cannot be read or written: one line naming it, not a stack trace.
    if (isFsError(err)) {
      process.stderr.write(`ssc ${name}: cannot ${err.syscall}${err.path ? ` ${err.path}` : ''}: ${fsReason(err)}\n`);
      return 1;
    }
    throw err;
  }
}

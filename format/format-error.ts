// A file that does not follow its format: the message names the file and what is wrong.

export class FormatError extends Error {
  readonly file: string | undefined;

  constructor(message: string, file?: string) {
    super(file ? `${file}: ${message}` : message);
    this.name = 'FormatError';
    this.file = file;
  }
}

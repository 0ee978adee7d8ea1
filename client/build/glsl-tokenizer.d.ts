// glsl-tokenizer's synchronous API (the package has no types of its own), as glsl-minify.ts uses it.
declare module 'glsl-tokenizer/string' {
  export interface GlslToken {
    /** 'block-comment', 'line-comment', 'preprocessor' (a whole # line), 'whitespace', 'eof', and the language's kinds. */
    type: string;
    data: string;
  }
  export default function tokenize(source: string, options?: { version?: string }): GlslToken[];
}

// The values a style is made of, as valibot schemas with the messages a cartographer reads.
// Messages do not name the field: describeIssues (schema-issues.ts) puts its path in front.
import * as v from 'valibot';

const HEX = /^#[0-9a-fA-F]{6}$/;
export const hex = () => v.pipe(v.string('must be a colour "#rrggbb"'), v.regex(HEX, 'must be a colour "#rrggbb"'));
export const finite = () => v.pipe(v.number('must be a number'), v.finite('must be a finite number'));
export const unit = () => v.pipe(finite(), v.minValue(0, 'must be in [0, 1]'), v.maxValue(1, 'must be in [0, 1]'));
export const positive = () => v.pipe(finite(), v.gtValue(0, 'must be a positive number'));
export const bool = () => v.boolean('must be true or false');
export const str = () => v.string('must be a string');

// The package ships an ES module at run time but its types as a CommonJS-style .ts file, so
// under NodeNext the default import is typed as the module object. One place sorts that out.
import ConstrainautorModule from '@kninnug/constrainautor';

type ConstrainautorClass = typeof ConstrainautorModule.default;
export type Constrainautor = InstanceType<ConstrainautorClass>;
export const Constrainautor: ConstrainautorClass =
  ((ConstrainautorModule as unknown as { default?: ConstrainautorClass }).default ?? ConstrainautorModule) as ConstrainautorClass;

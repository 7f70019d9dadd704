import type { ShellFlags } from '../app/route';
export default function Guide({ flags }: { flags: ShellFlags }) {
  return <main id="main" className="page" tabIndex={-1}><h1>Teacher’s guide</h1><p>{flags.present ? 'present' : ''}</p></main>;
}

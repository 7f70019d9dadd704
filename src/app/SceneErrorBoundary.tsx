import { Component, type ReactNode } from 'react';

/** A scene that throws shows what went wrong, with a retry and a link back to its defaults. */
export class SceneErrorBoundary extends Component<
  { children: ReactNode; resetKey: string },
  { error: string | null }
> {
  override state = { error: null as string | null };
  static getDerivedStateFromError(err: unknown) {
    return { error: err instanceof Error ? err.message : String(err) };
  }
  // a new query (the "reset" link, a typed URL, back/forward) gives the scene a fresh start
  override componentDidUpdate(prev: { resetKey: string }) {
    if (prev.resetKey !== this.props.resetKey && this.state.error !== null) this.setState({ error: null });
  }
  override render() {
    if (this.state.error) {
      return (
        <div role="alert" className="notice notice-error">
          <p>Something in this scene went wrong: {this.state.error}</p>
          <p>
            <button type="button" onClick={() => this.setState({ error: null })}>
              Try again
            </button>{' '}
            or{' '}
            <a href={window.location.hash.split('?')[0]} onClick={() => this.setState({ error: null })}>
              reset the scene to its defaults
            </a>
            .
          </p>
        </div>
      );
    }
    return this.props.children;
  }
}

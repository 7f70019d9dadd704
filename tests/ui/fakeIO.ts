/** A controllable IntersectionObserver for unit tests: the test says which elements are near the screen (and their box's width). */
export type FakeEntry = { target: object; isIntersecting: boolean; boundingClientRect: { width: number } };

export class FakeIO {
  static all: FakeIO[] = [];
  observed = new Set<object>();
  constructor(private cb: (entries: FakeEntry[]) => void) {
    FakeIO.all.push(this);
  }
  observe(el: object) {
    this.observed.add(el);
  }
  unobserve(el: object) {
    this.observed.delete(el);
  }
  disconnect() {
    this.observed.clear();
  }
  report(el: object, isIntersecting: boolean, width = 0) {
    if (this.observed.has(el)) this.cb([{ target: el, isIntersecting, boundingClientRect: { width } }]);
  }
}

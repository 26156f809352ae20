// Which panel elements are on screen (the side panel scrolls): what is scrolled away is not redrawn, and
// is redrawn at the next panel tick once it comes back (docs/performance.md, "Lab frame rate").
export class Visibility {
  private readonly shown = new Map<Element, boolean>();
  private readonly observer: IntersectionObserver | null;

  constructor() {
    this.observer =
      typeof IntersectionObserver === 'undefined'
        ? null
        : new IntersectionObserver((entries) => {
            for (const e of entries) this.shown.set(e.target, e.isIntersecting);
          });
  }

  /** Starts watching `el`; it counts as visible until the browser first says otherwise. */
  watch(el: Element): void {
    this.shown.set(el, true);
    this.observer?.observe(el);
  }

  visible(el: Element): boolean {
    return this.shown.get(el) ?? true;
  }
}

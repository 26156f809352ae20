// Recording the 3-D view to a WebM video (docs/web.md, "Recording"): the browser's MediaRecorder on the
// canvas's stream; stopping hands the video to `done` as a Blob. A recording stops by itself after
// MAX_RECORD_SECONDS, so its memory is bounded (at the default 2.5 Mbit/s, about 94 MB).

export const MAX_RECORD_SECONDS = 300;
const BITS_PER_SECOND = 2_500_000;

/** The first WebM type the browser records, or null. */
export function webmType(isSupported: (type: string) => boolean): string | null {
  for (const type of ['video/webm;codecs=vp9', 'video/webm;codecs=vp8', 'video/webm']) if (isSupported(type)) return type;
  return null;
}

export class Recorder {
  private recorder: MediaRecorder | null = null;
  private chunks: Blob[] = [];
  private timer: ReturnType<typeof setTimeout> | null = null;

  constructor(
    private readonly canvas: HTMLCanvasElement,
    private readonly done: (video: Blob) => void,
  ) {}

  get recording(): boolean {
    return this.recorder !== null;
  }

  /** Starts recording; returns a sentence saying why it cannot, or null. */
  start(): string | null {
    if (this.recorder !== null) return null;
    if (typeof MediaRecorder === 'undefined' || typeof this.canvas.captureStream !== 'function') return 'no MediaRecorder';
    const type = webmType((t) => MediaRecorder.isTypeSupported(t));
    if (type === null) return 'no WebM';
    const stream = this.canvas.captureStream(30);
    const rec = new MediaRecorder(stream, { mimeType: type, videoBitsPerSecond: BITS_PER_SECOND });
    this.chunks = [];
    rec.ondataavailable = (e) => {
      if (e.data.size > 0) this.chunks.push(e.data);
    };
    rec.onstop = () => {
      for (const track of stream.getTracks()) track.stop();
      this.done(new Blob(this.chunks, { type: 'video/webm' }));
      this.chunks = [];
    };
    rec.start(1000);
    this.recorder = rec;
    this.timer = setTimeout(() => this.stop(), MAX_RECORD_SECONDS * 1000);
    return null;
  }

  stop(): void {
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = null;
    const rec = this.recorder;
    this.recorder = null;
    if (rec !== null && rec.state !== 'inactive') rec.stop();
  }
}

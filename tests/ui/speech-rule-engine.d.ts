/** The part of speech-rule-engine's API the formula speech tests use (the package has no types). */
declare module 'speech-rule-engine' {
  export function setupEngine(options: Record<string, string>): Promise<void>;
  export function engineReady(): Promise<void>;
  export function toSpeech(mathml: string): string;
}

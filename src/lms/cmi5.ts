import type { CheckRecord } from '../practice/extensions';
import type { QuestionId } from '../practice/model';
import type { LmsConfig } from './packages';
import type { PracticeState } from './state';

export interface Cmi5Session {
  learnerName: string;
  state: PracticeState;
  onCheck(r: CheckRecord): Promise<void>;
  finish(): Promise<void>;
}

export async function connectCmi5(_c: LmsConfig, _q: QuestionId[]): Promise<Cmi5Session | null> {
  return null;
}

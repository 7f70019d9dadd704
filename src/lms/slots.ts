/** Registers the worksheet page's "For your LMS" section (the app loads this with practice). */
import { registerPracticeSlot } from '../practice/extensions';
import { LmsDownloads } from './LmsDownloads';

registerPracticeSlot('sheet', LmsDownloads);

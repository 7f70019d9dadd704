/** Registers "Download my results" on the practice pages (the app loads this with practice). */
import { registerPracticeSlot } from '../practice/extensions';
import { DownloadResults } from './DownloadResults';

registerPracticeSlot('question-footer', DownloadResults);
registerPracticeSlot('home-footer', DownloadResults);

/** Worker that measures FLIP between two images: runs the task of ./flipJobs off the main thread. */
import { exposeTasks } from './expose';
import { FLIP_TASKS } from './flipJobs';

exposeTasks(FLIP_TASKS);

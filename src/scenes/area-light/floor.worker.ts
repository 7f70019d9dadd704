/** Worker of #/area-light: runs the tasks of ./jobs off the main thread (cancel = terminate, src/workers/run.ts). */
import { exposeTasks } from '../../workers/expose';
import { AREA_LIGHT_TASKS } from './jobs';

exposeTasks(AREA_LIGHT_TASKS);

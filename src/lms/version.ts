/** The app's version, recorded in results files. */
import { version } from '../../package.json';

export const APP_VERSION: string = version;

export { Readout, readoutValue, formatNumber, type ReadoutProps } from './Readout';
export { NumberField, Slider, Select, Toggle, ExprField, Panel, Notice, SceneLayout, Transport } from './controls';
export { MathTex, loadKatex } from './MathTex';
export { Plot, loadPlotly, type PlotTrace, type PlotLayout } from './Plot';
export { useShortcuts, type ShortcutHandlers } from './shortcuts';
export { useSeenOnce, observeVisibility } from './useInView';
export { useTimeline, timelineParams, advance, clampPosition, prefersReducedMotion, TIMELINE_SPEEDS, type Timeline, type TimelineOptions } from './timeline';
export { TimelineTransport, type TimelineTransportProps } from './TimelineTransport';
export { ExamQuestion, ExamPart, Derivation, LiveAnswer, KeyNote, ExploreFurther, QuestionNav, questionHref } from './exam';

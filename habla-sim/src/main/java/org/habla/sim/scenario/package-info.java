/**
 * Scenario: the results of a scenario's episodes — obedience per phase, distance to the target over time,
 * reaching it — and the report written from them ({@code report.json}, {@code report.md}, SVG plots).
 */
package org.habla.sim.scenario;

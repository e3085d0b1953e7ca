package org.habla.draw;

/**
 * An interface as drawn: a frame around the boxes of its channels the graph uses.
 *
 * @param id    the interface id
 * @param title the frame's caption: id, driver and address
 */
public record InterfaceGroup(String id, String title) {
}

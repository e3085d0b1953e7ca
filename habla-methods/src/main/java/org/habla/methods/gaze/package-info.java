/** Where a robot looks: head poses, head joint limits and the head control that keeps a camera on a target. */
package org.habla.methods.gaze;

/** Where things are: turning what a sensor saw (a range reading, a blob in an image) into positions in the robot's and the world's frames. */
package org.habla.methods.position;

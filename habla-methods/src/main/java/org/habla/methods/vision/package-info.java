/** Vision methods of the processing layer: colour segmentation of camera frames with OpenCV. */
package org.habla.methods.vision;

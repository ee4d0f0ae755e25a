package io.github.jdem846.overlay;

import io.github.jdem846.projection.ProjectedPicture;
import io.github.jdem846.raster.GridGeometry;
import io.github.jdem846.raster.PixelAnchor;
import java.util.List;

/**
 * Overlays drawn onto a picture in a map projection ({@link io.github.jdem846.projection.ProjectedRender}): the
 * shapes are transformed into the projection's CRS (Apache SIS) and placed on the picture's pixels, whose edges
 * are the {@linkplain ProjectedPicture#extent() extent}'s; shapes in longitude and latitude are cut at the map's
 * edges, the meridian opposite the central one and the latitude limit ({@link OverlayPainter#onMap}).
 */
public final class ProjectedOverlays {

    private ProjectedOverlays() {
    }

    /**
     * {@return the grid of a projected picture's pixels: pixel (c, r) covers [west + c·w, west + (c+1)·w) ×
     * (north − (r+1)·h, north − r·h] in the projection's CRS}
     *
     * @param picture the projected picture
     */
    public static GridGeometry gridOf(ProjectedPicture picture) {
        double cellWidth = picture.extent().width() / picture.width();
        double cellHeight = picture.extent().height() / picture.height();
        return new GridGeometry(picture.width(), picture.height(), picture.extent().west(), picture.extent().north(),
                cellWidth, cellHeight, picture.projection().crsInfo(), PixelAnchor.CORNER);
    }

    /**
     * @param picture  the projected picture
     * @param overlays the overlays, drawn in this order
     * @return a copy of the picture with the overlays drawn on top
     * @throws IllegalArgumentException when an overlay cannot be transformed into the projection's CRS, naming it
     */
    public static ProjectedPicture paint(ProjectedPicture picture, List<Overlay> overlays) {
        OverlayPainter painter = OverlayPainter.onMap(overlays, gridOf(picture),
                picture.projection().centralMeridian(), picture.projection().latitudeLimit());
        int[] argb = picture.argb().clone();
        painter.paintRows(argb, 0, picture.height());
        return new ProjectedPicture(picture.projection(), picture.extent(), picture.width(), picture.height(), argb);
    }
}

package io.github.jdem846.tiles;

import java.io.Serializable;
import java.util.Objects;

/**
 * One finished tile: its place and its PNG file's bytes. Serializable, so that a cluster's task can return it.
 *
 * @param tile where it goes
 * @param png  the whole PNG file (the array is shared, not copied)
 * @serial exclude
 */
public record EncodedTile(WebMercatorTile tile, byte[] png) implements Serializable {

    private static final long serialVersionUID = 1L;

    /**
     * Checks that the tile and its bytes are given.
     *
     * @param tile where it goes
     * @param png the whole PNG file (the array is shared, not copied)
     */
    public EncodedTile {
        Objects.requireNonNull(tile, "tile");
        Objects.requireNonNull(png, "png");
    }
}

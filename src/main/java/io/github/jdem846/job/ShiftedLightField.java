package io.github.jdem846.job;

import io.github.jdem846.light.LightDirection;
import io.github.jdem846.light.LightField;

/**
 * The light of a picture seen from a grid in which the picture starts at column {@code col}, row {@code row}: cell
 * (c, r) of that grid is the picture's cell (c − col, r − row). A grid read with a halo, or a tile of the picture
 * with its halo, is then lit exactly as the picture is, whatever part of it was read.
 *
 * @param picture the light over the picture
 * @param col     the picture's first column in the grid (negative when the grid starts inside the picture)
 * @param row     the picture's first row in the grid
 */
record ShiftedLightField(LightField picture, int col, int row) implements LightField {

    @Override
    public LightDirection at(int c, int r) {
        return picture.at(c - col, r - row);
    }

    @Override
    public LightDirection central() {
        return picture.central();
    }

    @Override
    public boolean isUniform() {
        return picture.isUniform();
    }
}

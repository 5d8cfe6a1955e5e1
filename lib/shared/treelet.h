/* placeholder: treelet arithmetic shared by CPU and OpenCL */
